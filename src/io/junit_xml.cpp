#include "io/junit_xml.hpp"

#include <cstdint>

#include "io/format.hpp"
#include "io/printable.hpp"

namespace dlpverify {

namespace {

// `text` as XML character data or an attribute value (XML 1.0 §2.2, §2.4): the five special
// characters as entities, every character XML cannot carry (C0 controls but tab, newline and
// carriage return; U+FFFE, U+FFFF) and every byte outside well-formed UTF-8 as U+FFFD.
std::string xml_text(const std::string& text) {
  static const std::string replacement = "\xEF\xBF\xBD";
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    const auto b = static_cast<std::uint8_t>(text[i]);
    const std::string_view piece(text.data() + i, n == 0 ? 1 : n);
    i += piece.size();
    if (n == 0 || (b < 0x20 && b != '\t' && b != '\n' && b != '\r') || piece == "\xEF\xBF\xBE" || piece == "\xEF\xBF\xBF")
      out += replacement;
    else if (b == '&') out += "&amp;";
    else if (b == '<') out += "&lt;";
    else if (b == '>') out += "&gt;";
    else if (b == '"') out += "&quot;";
    else if (b == '\'') out += "&apos;";
    else out += piece;
  }
  return out;
}

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
  xml += "    <testcase name=\"" + xml_text(c.name) + "\" classname=\"" + xml_text(c.classname) + "\" time=\"" +
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
  if (c.result == JunitCase::Result::skipped) {  // text alone in the schema
    xml += ">";
    xml += xml_text(c.body.empty() ? c.message : c.body);
  } else {
    xml += " message=\"";
    xml += xml_text(c.message);
    xml += "\"";
    if (c.body.empty()) {
      xml += "/>\n    </testcase>\n";
      return;
    }
    xml += ">";
    xml += xml_text(c.body);
  }
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
    body += "  <testsuite name=\"" + xml_text(suite.name) + "\" " + counts.attributes(true) + ">\n";
    for (const JunitCase& c : suite.cases) add_case(body, c);
    body += "  </testsuite>\n";
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"dlpverify\" " + all.attributes(false) + ">\n" + body +
         "</testsuites>\n";
}

}  // namespace dlpverify
