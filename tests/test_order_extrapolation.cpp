// The order extrapolated from pairwise orders (docs/verification.md, "An order extrapolated from
// the pairwise orders"): Aitken's Δ² on pairwise orders that converge geometrically, refused on
// a pure power law (the orders stand still) and on oscillating orders, and judged by `check`
// like a fitted order — a method of the wrong order is not rescued.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <optional>
#include <vector>

#include "dlpverify/check.hpp"
#include "dlpverify/level_search.hpp"
#include "dlpverify/order_extrapolation.hpp"
#include "dlpverify/study.hpp"

namespace unit_order_extrapolation {

using namespace dlpverify;
namespace tt = boost::test_tools;

namespace {

// Pairwise orders of e_k = h_k^p (1 + 3 h_k), h_k = 0.1 / 2^k, k = 0 … 4, in closed form:
// p_k = p + log2((1 + 3 h_{k−1}) / (1 + 3 h_k)), k = 1 … 4.
std::vector<double> pairwise_with_dt5_term(double p) {
  std::vector<double> orders;
  for (int k = 1; k < 5; ++k) {
    const double coarse = 0.1 / std::pow(2.0, k - 1), fine = coarse / 2.0;
    orders.push_back(p + std::log2((1.0 + 3.0 * coarse) / (1.0 + 3.0 * fine)));
  }
  return orders;
}

// Levels from Δt_0 = 0.1 (ratio 2) over t_end = 1, checked against order 4.
StudyPlan plan_with_dt5_term() {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.ratio = 2.0;
  plan.expected_order = 4.0;
  plan.variables = {{"y", 0, 1, "1"}};
  return plan;
}

// A level's state whose L2 error is Δt^p (1 + 3 Δt) against the exact reference (0, 1); the
// second, exact member gives the solution size 1.
Solve solve_with_dt5_term(double p) {
  return [p](double dt, long, SolverStatistics&) {
    State y(2, 1);
    y << std::pow(dt, p) * (1.0 + 3.0 * dt), 1.0;
    return y;
  };
}

State exact_reference() {
  State reference(2, 1);
  reference << 0.0, 1.0;
  return reference;
}

// Five levels Δt_k = 0.1 / 2^k of those errors, run through the harness's study loop (norms,
// level rules, fit).
StudyResult study_with_dt5_term(double p) {
  StudyPlan plan = plan_with_dt5_term();
  plan.levels = 5;
  return run_study(plan, exact_reference(), {0.0}, solve_with_dt5_term(p));
}

// A level search from Δt_0 = 0.1 (ratio 2, t_end = 1) on errors Δt^p (1 + 3Δt) against a
// reference whose estimated error is e_2 / 200: levels 0 … 2 are trusted (margin 200), level 3 is
// not (margin 200 e_3 / e_2 ≈ 12 for p = 4): the search stops on the reference's accuracy with two
// pairwise orders, and refines on for the self-differences. The wall-time budget is the largest
// the command allows (1e7 s), so the search ends on its counted rules on any machine.
StudyResult search_with_dt5_term(double p, LevelSearch& search) {
  const double e2 = std::pow(0.025, p) * (1.0 + 3.0 * 0.025);
  LevelSearchRules rules;
  rules.budget_seconds = 1e7;
  return search_levels(plan_with_dt5_term(), exact_reference(), {e2 / 200.0}, solve_with_dt5_term(p), rules,
                       search);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(order_extrapolation)

// p_k = 4.177, 4.097, 4.051, 4.026 (closed form above): gaps −0.080, −0.046, −0.025, ratios 0.579
// and 0.541 (→ 1/2, the Δt⁵ term). Aitken on the last three gives 3.99697 (by hand: 4.02631 −
// 0.02491² / 0.02116), within 0.004 of 4, and the half-width 0.0384 (0.0294 step + 0.0090 spread
// to 4.00601 one level coarser) holds the true limit 4.
// A level search that stopped on the reference's accuracy with these extrapolations, as
// check_orders reads one.
const LevelSearch& stopped_with(std::vector<std::optional<OrderExtrapolation>> extrapolations) {
  static LevelSearch search;
  search = LevelSearch{};
  search.stop = SearchStop::reference_accuracy;
  search.extrapolations = std::move(extrapolations);
  return search;
}

BOOST_AUTO_TEST_CASE(dt5_term_extrapolates_to_the_order) {
  const OrderExtrapolation x = extrapolate_order(pairwise_with_dt5_term(4.0));
  BOOST_TEST_REQUIRE(x.computed, x.refusal);
  BOOST_TEST(x.value == 3.9969741641713883, tt::tolerance(1e-9));
  BOOST_TEST(std::abs(x.value - 4.0) < 0.004);
  BOOST_TEST(x.half_width == 0.03843126517034845, tt::tolerance(1e-8));
  BOOST_TEST(std::abs(x.value - 4.0) <= x.half_width);
  BOOST_TEST(x.pairwise.size() == 4u);
  BOOST_TEST_REQUIRE(x.gap_ratios.size() == 2u);
  BOOST_TEST(x.gap_ratios[0] == 0.5789338197369398, tt::tolerance(1e-9));
  BOOST_TEST(x.gap_ratios[1] == 0.5407647207145386, tt::tolerance(1e-9));
  BOOST_TEST(to_json(x)["method"] == "aitken");
}

// Three pairwise orders are enough (one Aitken step, no spread); two are not.
BOOST_AUTO_TEST_CASE(three_orders_are_the_fewest) {
  std::vector<double> p = pairwise_with_dt5_term(4.0);
  p.erase(p.begin());
  const OrderExtrapolation three = extrapolate_order(p);
  BOOST_TEST_REQUIRE(three.computed);
  BOOST_TEST(three.half_width == std::abs(three.value - p.back()), tt::tolerance(1e-12));
  p.erase(p.begin());
  const OrderExtrapolation two = extrapolate_order(p);
  BOOST_TEST(!two.computed);
  BOOST_TEST(two.refusal.find("has 2") != std::string::npos, two.refusal);
}

// A pure power law: every pairwise order is 4 to rounding, nothing moves, nothing is extrapolated.
BOOST_AUTO_TEST_CASE(pure_power_law_is_refused) {
  const OrderExtrapolation x = extrapolate_order(std::vector<double>{4.0, 4.0 + 1e-13, 4.0 - 1e-13, 4.0});
  BOOST_TEST(!x.computed);
  BOOST_TEST(x.refusal.find("do not move") != std::string::npos, x.refusal);
}

// Orders that oscillate about 4 (gap ratios −1) or move away from it (ratio 2), or whose gap
// ratios differ by more than 2 x (0.2 then 0.9), are no geometric convergence: refused.
BOOST_AUTO_TEST_CASE(oscillating_or_irregular_orders_are_refused) {
  for (const std::vector<double>& p : {std::vector<double>{4.1, 3.9, 4.1, 3.9}, std::vector<double>{4.01, 4.02, 4.04},
                                       std::vector<double>{4.5, 4.0, 3.9, 3.81}}) {
    const OrderExtrapolation x = extrapolate_order(p);
    BOOST_TEST(!x.computed, x.refusal);
    BOOST_TEST(!x.refusal.empty());
  }
}

// Through the study loop: the errors Δt⁴ (1 + 3Δt) give the closed-form pairwise orders 4.18,
// 4.10, 4.05, 4.03; levels 0–1 are pre-asymptotic (their pairwise orders are still extrapolated
// from) and the window 2–4 fits 4.038, outside 4 ± 0.03 (inconclusive: still moving towards 4);
// judged by the extrapolated order, check passes at 4 ± 0.03.
BOOST_AUTO_TEST_CASE(check_judges_by_the_extrapolated_order) {
  const StudyResult study = study_with_dt5_term(4.0);
  const OrderExtrapolation x = extrapolate_order(study.orders[0]);
  BOOST_TEST_REQUIRE(x.computed, x.refusal);
  BOOST_TEST(x.value == 3.9969741641713883, tt::tolerance(1e-8));

  BOOST_TEST(!check_orders(study, 4.0, 0.03).passed());
  BOOST_TEST(study.orders[0].fit.value == 4.038, tt::tolerance(1e-3));
  // A pass by extrapolation needs the whole extrapolate in the band, |p∞ − P| + w ≤ tol: inside
  // 4 ± 0.03 by its value alone, it is inconclusive while its half-width reaches out of the band.
  const double reach = std::abs(x.value - 4.0) + x.half_width;
  const CheckVerdict narrow = check_orders(study, 4.0, reach * 1.001, &stopped_with({x}));
  BOOST_TEST(narrow.passed(), narrow.findings[0].line());
  BOOST_TEST(narrow.findings[0].line().find("extrapolated") != std::string::npos, narrow.findings[0].line());
  const CheckVerdict too_wide = check_orders(study, 4.0, reach * 0.999, &stopped_with({x}));
  BOOST_TEST(too_wide.inconclusive(), too_wide.findings[0].line());
  if (reach > 0.03) BOOST_TEST(check_orders(study, 4.0, 0.03, &stopped_with({x})).inconclusive());

  // A refused extrapolation (none made) leaves the fitted order's verdict.
  BOOST_TEST(!check_orders(study, 4.0, 0.03, &stopped_with({std::nullopt})).passed());
}

// A third-order method with the same Δt⁴ companion term, e = Δt³ (1 + 3Δt), extrapolates to
// 2.997 (the same gaps, one order lower) and still fails at 4 ± 0.1: the extrapolation finds the
// order the errors have, it does not rescue a wrong one.
BOOST_AUTO_TEST_CASE(wrong_order_is_not_rescued) {
  const StudyResult study = study_with_dt5_term(3.0);
  const OrderExtrapolation x = extrapolate_order(study.orders[0]);
  BOOST_TEST_REQUIRE(x.computed, x.refusal);
  BOOST_TEST(x.value == 2.9969741641713816, tt::tolerance(1e-8));
  const CheckVerdict verdict = check_orders(study, 4.0, 0.1, &stopped_with({x}));
  BOOST_TEST(!verdict.passed());
  BOOST_TEST(verdict.has(CheckOutcome::order_miss));
}

// The reference trusts levels 0 … 2 only; the differences d_k = e_{k−1} − e_k of levels to 3.125 ms
// need none. Their pairwise orders in closed form, log2(d_{k−1} / d_k) with e = h⁴ (1 + 3h),
// h_k = 0.1 / 2^k: 4.18167, 4.10020, 4.05284, 4.02716 (gap ratios 0.581, 0.542); Aitken on the last
// three gives 3.99677, half-width 0.04011 (by the formulas of the header, evaluated in Python).
// The three levels beyond the reference's trust stay out of the fit, and check passes by it.
BOOST_AUTO_TEST_CASE(self_differences_extrapolate_beyond_the_reference) {
  LevelSearch search;
  const StudyResult study = search_with_dt5_term(4.0, search);
  BOOST_TEST(to_string(search.stop) == "reference-accuracy");
  BOOST_TEST(study.levels.size() == 3u);
  BOOST_TEST(study.orders[0].fit.levels.size() == 3u);
  BOOST_TEST_REQUIRE(search.run.size() == 6u);
  BOOST_TEST(search.run[5].dt == 0.003125, tt::tolerance(1e-12));
  for (std::size_t k = 3; k < 6; ++k) BOOST_TEST(!search.run[k].kept);
  BOOST_TEST_REQUIRE(search.extrapolations.size() == 1u);
  BOOST_TEST_REQUIRE(search.extrapolations[0].has_value());
  const OrderExtrapolation& x = *search.extrapolations[0];
  BOOST_TEST_REQUIRE(x.computed, x.refusal);
  BOOST_TEST(x.source == "self-differences");
  BOOST_TEST(x.reference_trusted_to == 0.025, tt::tolerance(1e-12));
  BOOST_TEST_REQUIRE(x.pairwise.size() == 4u);
  BOOST_TEST(x.pairwise[0] == 4.181673960121392, tt::tolerance(1e-9));
  BOOST_TEST(x.pairwise[3] == 4.0271636000584605, tt::tolerance(1e-9));
  BOOST_TEST(x.value == 3.9967692959780043, tt::tolerance(1e-9));
  BOOST_TEST(x.half_width == 0.040109435028232276, tt::tolerance(1e-8));
  BOOST_TEST(std::abs(x.value - 4.0) <= x.half_width);
  BOOST_TEST(to_json(x)["source"] == "self-differences");

  BOOST_TEST(!check_orders(study, 4.0, 0.1).passed());  // the fitted order over the three trusted levels, 4.14, is outside
  const CheckVerdict verdict = check_orders(study, 4.0, 0.1, &search);
  BOOST_TEST(verdict.passed());
  BOOST_TEST(verdict.findings[0].line().find("no reference needed") != std::string::npos, verdict.findings[0].line());
}

// The same with e = h³ (1 + 3h): the self-differences extrapolate to 2.99653 (closed form as
// above) and check at 4 ± 0.1 still fails: a wrong order is not rescued.
BOOST_AUTO_TEST_CASE(self_differences_do_not_rescue_a_wrong_order) {
  LevelSearch search;
  const StudyResult study = search_with_dt5_term(3.0, search);
  BOOST_TEST_REQUIRE(search.extrapolations.size() == 1u);
  BOOST_TEST_REQUIRE(search.extrapolations[0].has_value());
  const OrderExtrapolation& x = *search.extrapolations[0];
  BOOST_TEST_REQUIRE(x.computed, x.refusal);
  BOOST_TEST(x.source == "self-differences");
  BOOST_TEST(x.value == 2.9965269287345446, tt::tolerance(1e-9));
  const CheckVerdict verdict = check_orders(study, 4.0, 0.1, &search);
  BOOST_TEST(!verdict.passed());
  BOOST_TEST(verdict.has(CheckOutcome::order_miss));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_order_extrapolation
