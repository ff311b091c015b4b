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
  std::string message;  // the verdict's reason line, one line: the element's message attribute
  std::string body;     // the element's text (a skipped case's: the message when empty)
};

struct JunitProperty {
  std::string name;   // "position.order"
  std::string value;  // "2.02346"
};

struct JunitSuite {
  std::string name;  // the study ("drag-rk2")
  double seconds = 0.0;
  std::vector<JunitCase> cases;
  // Its <properties>, before the cases: the schema has them on a suite, not on a case.
  std::vector<JunitProperty> properties;
};

// The document, UTF-8: text that is not valid UTF-8 or holds characters XML 1.0 cannot carry
// (controls other than tab, newline and carriage return) is replaced by U+FFFD, and & < > " ' are
// escaped. Counts (tests, failures, errors; skipped per suite) are computed per suite and in all.
// A failure, an error and a skipped case alike carry the message as their `message` attribute and
// the body as their text (a skipped case's text is the message without a body): some reporters
// show only the attribute.
std::string junit_xml(const std::vector<JunitSuite>& suites);

}  // namespace dlpverify
