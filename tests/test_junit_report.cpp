// JUnit XML (io/junit_xml.hpp) against documents written out by hand: the counts per suite and in
// all, each result's element with its message, a suite's properties, and text no XML 1.0 document may hold (a control byte, a byte outside
// UTF-8, U+FFFF) replaced by U+FFFD while the five special characters become entities. The schema
// itself is checked by xmllint in cli.suite-junit.
#include <boost/test/unit_test.hpp>

#include <string>

#include "io/junit_xml.hpp"

namespace unit_junit_report {

using namespace dlpverify;
using Result = JunitCase::Result;

BOOST_AUTO_TEST_SUITE(junit_report)

BOOST_AUTO_TEST_CASE(every_result_and_its_counts) {
  const std::vector<JunitSuite> suites{
      {"a", 1.5, {{"x", "a", 0.75, Result::passed, "", ""}, {"y", "a", 0.75, Result::failure, "y: FAIL", "table"}}, {}},
      {"b", 0.25, {{"z", "b", 0.125, Result::skipped, "z: INCONCLUSIVE", "t"}, {"study", "b", 0.125, Result::error, "bad", ""}}, {}}};
  BOOST_TEST(junit_xml(suites) ==
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<testsuites name=\"dlpverify\" tests=\"4\" failures=\"1\" errors=\"1\" time=\"1.750\">\n"
             "  <testsuite name=\"a\" tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"0\" time=\"1.500\">\n"
             "    <testcase name=\"x\" classname=\"a\" time=\"0.750\"/>\n"
             "    <testcase name=\"y\" classname=\"a\" time=\"0.750\">\n"
             "      <failure message=\"y: FAIL\">table</failure>\n"
             "    </testcase>\n"
             "  </testsuite>\n"
             "  <testsuite name=\"b\" tests=\"2\" failures=\"0\" errors=\"1\" skipped=\"1\" time=\"0.250\">\n"
             "    <testcase name=\"z\" classname=\"b\" time=\"0.125\">\n"
             "      <skipped message=\"z: INCONCLUSIVE\">t</skipped>\n"
             "    </testcase>\n"
             "    <testcase name=\"study\" classname=\"b\" time=\"0.125\">\n"
             "      <error message=\"bad\"/>\n"
             "    </testcase>\n"
             "  </testsuite>\n"
             "</testsuites>\n");
}

// A skip without a text of its own takes the message as its text too (GitLab shows the text alone);
// a suite's properties come before its cases, as the schema has them, and none is no <properties>.
BOOST_AUTO_TEST_CASE(a_skip_keeps_its_message_and_properties_come_first) {
  JunitSuite with{"s", 1.0, {{"x", "s", 1.0, Result::skipped, "x: INCONCLUSIVE", ""}}, {{"x.order", "2.5"}, {"x.order_tolerance", "0.1"}}};
  BOOST_TEST(junit_xml({with}) ==
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<testsuites name=\"dlpverify\" tests=\"1\" failures=\"0\" errors=\"0\" time=\"1.000\">\n"
             "  <testsuite name=\"s\" tests=\"1\" failures=\"0\" errors=\"0\" skipped=\"1\" time=\"1.000\">\n"
             "    <properties>\n"
             "      <property name=\"x.order\" value=\"2.5\"/>\n"
             "      <property name=\"x.order_tolerance\" value=\"0.1\"/>\n"
             "    </properties>\n"
             "    <testcase name=\"x\" classname=\"s\" time=\"1.000\">\n"
             "      <skipped message=\"x: INCONCLUSIVE\">x: INCONCLUSIVE</skipped>\n"
             "    </testcase>\n"
             "  </testsuite>\n"
             "</testsuites>\n");
  with.properties.clear();
  BOOST_TEST(junit_xml({with}).find("properties") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(text_xml_cannot_hold_is_replaced) {
  const std::string hostile = std::string("a&b<c>d\"e'f\x1b[2J\x01g\xff\xfe") + "h\xEF\xBF\xBFi\tj]]>k" + "\xCE\x94t";
  const std::string xml = junit_xml({{"s", 0.0, {{hostile, "c", 0.0, Result::failure, hostile, hostile}}, {}}});
  const std::string escaped =
      "a&amp;b&lt;c&gt;d&quot;e&apos;f\xEF\xBF\xBD[2J\xEF\xBF\xBDg\xEF\xBF\xBD\xEF\xBF\xBDh\xEF\xBF\xBDi\tj]]&gt;k\xCE\x94t";
  BOOST_TEST(xml.find("<testcase name=\"" + escaped + "\"") != std::string::npos, xml);
  BOOST_TEST(xml.find("<failure message=\"" + escaped + "\">" + escaped + "</failure>") != std::string::npos, xml);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_junit_report
