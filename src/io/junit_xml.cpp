#include "io/junit_xml.hpp"

#include "io/format.hpp"
#include "io/markup.hpp"

namespace dlpverify {

namespace {

struct Counts {
  int tests = 0, failures = 0, errors = 0, skipped = 0;
  double seconds = 0.0;
  void add(const JunitCase& c) {
    ++tests;
    failures += c.result == JunitCase::Result::failure;
    errors += c.result == JunitCase::Result::error;
    skipped += c.result == JunitCase::Result::skipped;
  }
  // <testsuites> has no skipped count in the schema; <testsuite> has.
  std::string attributes(bool with_skipped) const {
    return printf_string("tests=\"%d\" failures=\"%d\" errors=\"%d\"", tests, failures, errors) +
           (with_skipped ? printf_string(" skipped=\"%d\"", skipped) : "") + printf_string(" time=\"%.3f\"", seconds);
  }
};

void add_case(std::string& xml, const JunitCase& c) {
  xml += "    <testcase name=\"" + markup_text(c.name) + "\" classname=\"" + markup_text(c.classname) + "\" time=\"" +
         printf_string("%.3f", c.seconds) + "\"";
  const char* element = c.result == JunitCase::Result::failure ? "failure"
                        : c.result == JunitCase::Result::skipped ? "skipped"
                        : c.result == JunitCase::Result::error   ? "error"
                                                                  : nullptr;
  if (!element) {
    xml += "/>\n";
    return;
  }
  // Appended piece by piece: GCC 12 misreads "…" + std::string&& (a false -Wrestrict).
  xml += ">\n      <";
  xml += element;
  xml += " message=\"";
  xml += markup_text(c.message);
  xml += "\"";
  // A skip's reason is its text too: GitLab shows the text alone.
  const std::string& text = c.result == JunitCase::Result::skipped && c.body.empty() ? c.message : c.body;
  if (text.empty()) {
    xml += "/>\n    </testcase>\n";
    return;
  }
  xml += ">";
  xml += markup_text(text);
  xml += "</";
  xml += element;
  xml += ">\n    </testcase>\n";
}

}  // namespace

std::string junit_xml(const std::vector<JunitSuite>& suites) {
  Counts all;
  std::string body;
  for (const JunitSuite& suite : suites) {
    Counts counts;
    counts.seconds = suite.seconds;
    for (const JunitCase& c : suite.cases) counts.add(c), all.add(c);
    all.seconds += suite.seconds;
    body += "  <testsuite name=\"" + markup_text(suite.name) + "\" " + counts.attributes(true) + ">\n";
    if (!suite.properties.empty()) {  // the schema's <properties> holds at least one
      body += "    <properties>\n";
      for (const JunitProperty& p : suite.properties)
        body += "      <property name=\"" + markup_text(p.name) + "\" value=\"" + markup_text(p.value) + "\"/>\n";
      body += "    </properties>\n";
    }
    for (const JunitCase& c : suite.cases) add_case(body, c);
    body += "  </testsuite>\n";
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"dlpverify\" " + all.attributes(false) + ">\n" + body +
         "</testsuites>\n";
}

}  // namespace dlpverify
