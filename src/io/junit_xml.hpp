// JUnit XML, the test report GitLab, Jenkins and GitHub's test reporters read: <testsuites>
// holding one <testsuite> per study and one <testcase> per judged variable, with a <failure>,
// <skipped> or <error> child where the case did not pass. The element and attribute names follow
// the schema Jenkins' JUnit plugin validates against (junit-4.xsd), which GitLab reads as well.
// Written by hand: no Debian package writes JUnit XML from C++, and the format is these few
// elements.
#pragma once

#include <string>
#include <vector>

namespace dlpverify {

struct JunitCase {
  enum class Result { passed, failure, skipped, error };
  std::string name;       // the variable ("position"), stable across runs
  std::string classname;  // the study it belongs to ("drag-rk2")
  double seconds = 0.0;
  Result result = Result::passed;
  std::string message;  // the verdict's reason line: a failure's or an error's message attribute
  std::string body;     // the element's text (a skipped case's only one; the message when empty)
};

struct JunitSuite {
  std::string name;  // the study ("drag-rk2")
  double seconds = 0.0;
  std::vector<JunitCase> cases;
};

// The document, UTF-8: text that is not valid UTF-8 or holds characters XML 1.0 cannot carry
// (controls other than tab, newline and carriage return) is replaced by U+FFFD, and & < > " ' are
// escaped. Counts (tests, failures, errors; skipped per suite) are computed per suite and in all;
// <skipped> takes no attribute in the schema: its text is the body, or the message without one.
std::string junit_xml(const std::vector<JunitSuite>& suites);

}  // namespace dlpverify
