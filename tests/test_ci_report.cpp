// A study's verdicts as a CI reads them (case_study/ci_report.hpp): of several findings of one
// variable the most severe decides its JUnit case and its reason, the cases share the study's time
// (they add up to it), a failed or skipped case carries its finding as a one-line message, and the
// properties carry each variable's fitted order, interval, band and error constant by stable names.
#include <boost/test/unit_test.hpp>

#include <limits>
#include <string>

#include "case_study/ci_report.hpp"

namespace unit_ci_report {

using namespace dlpverify;
using namespace dlpverify::case_study;

// Two variables, position judged twice: its order passes, its constant (a later gate) fails;
// velocity's order is inconclusive, then an order finding of the same variable passes.
CheckVerdict two_gates() {
  CheckVerdict verdict;
  verdict.expected_order = 2.0;
  verdict.tolerance = 0.1;
  verdict.findings = {{0, "position", Criterion::order, CheckOutcome::order_within, "pass, fitted order 2.010"},
                      {1, "velocity", Criterion::order, CheckOutcome::inconclusive, "INCONCLUSIVE, still moving"},
                      {0, "position", Criterion::error_constant, CheckOutcome::constant_outside, "FAIL, error constant\noutside"},
                      {1, "velocity", Criterion::error_constant, CheckOutcome::constant_within, "pass, error constant within"}};
  return verdict;
}

std::vector<Variable> variables() { return {{"position", 0, 3, "m"}, {"velocity", 3, 3, "m/s"}}; }

BOOST_AUTO_TEST_SUITE(ci_report)

BOOST_AUTO_TEST_CASE(the_most_severe_finding_decides_a_variable) {
  const std::vector<VariableVerdict> verdicts = variable_verdicts(variables(), two_gates());
  BOOST_REQUIRE(verdicts.size() == 2u);
  BOOST_TEST((verdicts[0].result == FindingResult::fail));
  BOOST_TEST(verdicts[0].finding == "FAIL, error constant\noutside");
  BOOST_TEST((verdicts[1].result == FindingResult::inconclusive));
  BOOST_TEST(verdicts[1].finding == "INCONCLUSIVE, still moving");
  CaseOutcome outcome;
  outcome.verdicts = verdicts;
  const JunitSuite suite = junit_suite("s", outcome);
  BOOST_REQUIRE(suite.cases.size() == 2u);
  BOOST_TEST((suite.cases[0].result == JunitCase::Result::failure));
  BOOST_TEST(suite.cases[0].message == "position: FAIL, error constant outside");  // one line
  BOOST_TEST((suite.cases[1].result == JunitCase::Result::skipped));
  BOOST_TEST(suite.cases[1].message == "velocity: INCONCLUSIVE, still moving");
}

BOOST_AUTO_TEST_CASE(the_cases_share_the_study_time) {
  CaseOutcome outcome;
  outcome.seconds = 0.9;
  outcome.verdicts = variable_verdicts(std::vector<Variable>{{"a", 0, 1, ""}, {"b", 1, 1, ""}, {"c", 2, 1, ""}},
                                       CheckVerdict{2.0, {}, 0.1, {{0, "a", Criterion::order, CheckOutcome::order_within, "pass"},
                                                                   {1, "b", Criterion::order, CheckOutcome::order_within, "pass"},
                                                                   {2, "c", Criterion::order, CheckOutcome::order_within, "pass"}}});
  const JunitSuite suite = junit_suite("s", outcome);
  BOOST_REQUIRE(suite.cases.size() == 3u);
  double sum = 0.0;
  for (const JunitCase& c : suite.cases) {
    BOOST_TEST(c.seconds == 0.3, boost::test_tools::tolerance(1e-12));
    sum += c.seconds;
  }
  BOOST_TEST(sum == suite.seconds, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(properties_carry_order_interval_band_and_constant) {
  VariableVerdict v;
  v.variable = "position";
  v.expected = 2.0;
  v.tolerance = 0.1;
  v.fit.valid = true;
  v.fit.value = 2.0234567;
  v.fit.ci_low = 2.0021;
  v.fit.ci_high = 2.0448;
  v.constant.valid = true;
  v.constant.order = 2.0;
  v.constant.value = 1.2345678e-3;
  // A method off its order has its constant at the order its errors show: no point of C's trend at P.
  VariableVerdict off_order = v;
  off_order.variable = "temperature";
  off_order.fit.value = 1.0049;
  off_order.fit.ci_low = 0.9912;
  off_order.fit.ci_high = 1.0186;
  off_order.constant.order = 1.0;
  VariableVerdict two_levels = v;  // no interval with two levels, no constant, a sweep's exponent
  two_levels.variable = "velocity";
  two_levels.quantity = "exponent";
  two_levels.fit.ci_low = two_levels.fit.ci_high = std::numeric_limits<double>::quiet_NaN();
  two_levels.constant.valid = false;
  const std::vector<JunitProperty> p = junit_properties({v, off_order, two_levels});
  std::string all;
  for (const JunitProperty& one : p) all += one.name + "=" + one.value + "\n";
  BOOST_TEST(all ==
             "position.order=2.02346\nposition.order_low=2.0021\nposition.order_high=2.0448\n"
             "position.expected_order=2\nposition.order_tolerance=0.1\nposition.error_constant=0.00123457\n"
             "temperature.order=1.0049\ntemperature.order_low=0.9912\ntemperature.order_high=1.0186\n"
             "temperature.expected_order=2\ntemperature.order_tolerance=0.1\n"
             "velocity.exponent=2.02346\nvelocity.expected_exponent=2\nvelocity.exponent_tolerance=0.1\n");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_ci_report
