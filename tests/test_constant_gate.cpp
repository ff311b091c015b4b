// The baseline gate and compare on recorded results (harness/constant_gate.hpp, comparison.hpp,
// recorded_study.hpp): the band |C − C_base| ≤ tol × C_base at its edges, what makes two results
// one study, and the verdict of compare — on hand-made results whose numbers are the test's own.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "dlpverify/errors.hpp"
#include "harness/comparison.hpp"
#include "harness/constant_gate.hpp"
#include "dlpverify/recorded_study.hpp"

namespace unit_constant_gate {

using namespace dlpverify;
using nlohmann::json;

namespace {

// A two-level result of case `name` whose one variable y has error constant C at order 2.
json result(const std::string& name, double constant, double order = 2.0, long steps0 = 10) {
  return {{"case", name},
          {"integrator", "test"},
          {"reference", "exact"},
          {"particles", 3},
          {"t0", 0.0},
          {"t_end", 1.0},
          {"ratio", 2.0},
          {"variables", {"y"}},
          {"parameters", {{"k", 1.5}}},
          {"levels",
           {{{"dt", 1.0 / steps0}, {"steps", steps0}, {"l2_y", 0.01}, {"order_y", nullptr}},
            {{"dt", 0.5 / steps0}, {"steps", 2 * steps0}, {"l2_y", 0.0025}, {"order_y", 2.0}}}},
          {"fitted_order", {{"y", {{"value", order}, {"exact_to_round_off", false}}}}},
          {"error_constant", {{"y", {{"value", constant}, {"order", 2.0}, {"ci95", nullptr}, {"levels_used", {0, 1}}}}}}};
}

RecordedStudy read(const json& j) { return read_recorded_study(j, "test.json", "input"); }

}  // namespace

BOOST_AUTO_TEST_SUITE(constant_gate)

// The band's edges: 4.9% in, 5.1% out, in either direction, and the ratio C / C_base.
BOOST_AUTO_TEST_CASE(band_edges) {
  const RecordedStudy base = read(result("a", 2.0));
  for (double factor : {1.049, 0.951}) {
    const ConstantComparison c = compare_constants(base.variables[0], read(result("a", 2.0 * factor)).variables[0], 0.05);
    BOOST_TEST(c.agree, factor);
    BOOST_TEST(std::abs(c.ratio - factor) < 1e-14);
  }
  for (double factor : {1.051, 0.949})
    BOOST_TEST(!compare_constants(base.variables[0], read(result("a", 2.0 * factor)).variables[0], 0.05).agree, factor);
}

// A constant on one side only, or at two orders, never agrees; exact to round-off in both does.
BOOST_AUTO_TEST_CASE(missing_constants_and_orders) {
  const RecordedVariable with = read(result("a", 2.0)).variables[0];
  json none = result("a", 2.0);
  none["error_constant"]["y"] = nullptr;
  RecordedVariable without = read(none).variables[0];
  BOOST_TEST(!compare_constants(with, without, 0.05).agree);
  BOOST_TEST(!compare_constants(without, with, 0.05).agree);
  BOOST_TEST(!compare_constants(without, without, 0.05).agree);  // neither exact: nothing was measured
  without.exact_to_round_off = true;
  BOOST_TEST(compare_constants(without, without, 0.05).agree);
  json other = result("a", 2.0);
  other["error_constant"]["y"]["order"] = 1.0;
  BOOST_TEST(!compare_constants(with, read(other).variables[0], 0.05).agree);
}

// The gate only adds a condition: the verdict passes when the orders passed AND every constant
// agrees. An order that failed is not rescued by a constant inside its band; a passing order
// fails on a constant outside it; one finding and outcome is appended per variable either way.
BOOST_AUTO_TEST_CASE(the_gate_never_rescues_a_failed_order) {
  const RecordedStudy base = read(result("a", 2.0));
  const RecordedStudy within = read(result("a", 2.0 * 1.01)), outside = read(result("a", 2.0 * 1.2));
  struct Case {
    bool orders_passed;
    const RecordedStudy* now;
    bool passed;  // orders_passed ∧ |C − C_base| ≤ 5% C_base
  };
  for (const Case& c : {Case{false, &within, false}, Case{false, &outside, false}, Case{true, &within, true},
                        Case{true, &outside, false}}) {
    CheckVerdict verdict;
    verdict.findings = {{0, "y", Criterion::order, c.orders_passed ? CheckOutcome::order_within : CheckOutcome::order_miss,
                         "order finding"}};
    check_constants(*c.now, base, 0.05, verdict);
    BOOST_TEST(verdict.passed() == c.passed,
               "orders passed " << c.orders_passed << ", C " << c.now->variables[0].constant->value);
    BOOST_TEST_REQUIRE(verdict.findings.size() == 2u);
    const CheckOutcome constant = c.now == &within ? CheckOutcome::constant_within : CheckOutcome::constant_outside;
    BOOST_TEST((verdict.findings[1].outcome == constant));
    BOOST_TEST((verdict.findings[1].criterion == Criterion::error_constant));
    BOOST_TEST(verdict.findings[1].variable == 0u);
  }
}

// One study: the same case, parameters and levels; the first difference is named.
BOOST_AUTO_TEST_CASE(what_makes_one_study) {
  const RecordedStudy a = read(result("a", 2.0));
  BOOST_TEST(study_difference(a, read(result("a", 9.0))).empty());  // the integrator's constant may differ
  BOOST_TEST(study_difference(a, read(result("b", 2.0))) == "its case is \"b\", not \"a\"");
  json parameters = result("a", 2.0);
  parameters["parameters"]["k"] = 2.5;
  BOOST_TEST(study_difference(a, read(parameters)) == "parameters k is 2.5, not 1.5");
  BOOST_TEST(study_difference(a, read(result("a", 2.0, 2.0, 20))) ==
             "its level 0 takes 20 steps of dt 0.05, not 10 of 0.1");
  json old = result("a", 2.0);
  old.erase("error_constant");
  BOOST_CHECK_THROW(read(old), InputError);  // written before results recorded their constants
}

// compare agrees within both tolerances and names what differs; two studies are bad input.
BOOST_AUTO_TEST_CASE(compare_verdict) {
  const RecordedStudy a = read(result("a", 2.0));
  BOOST_TEST(compare_studies(a, read(result("a", 2.05, 2.09)), {}).agree);
  const StudyComparison order = compare_studies(a, read(result("a", 2.0, 2.11)), {});
  BOOST_TEST(!order.agree);
  BOOST_TEST(!order.variables[0].orders_agree);
  BOOST_TEST(order.variables[0].constant.agree);
  BOOST_TEST(!compare_studies(a, read(result("a", 2.2)), {}).agree);
  BOOST_CHECK_THROW(compare_studies(a, read(result("b", 2.0)), {}), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_constant_gate
