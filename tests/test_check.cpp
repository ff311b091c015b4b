// The `check` verdict (docs/verification.md, "What check decides"): pass when the fitted order is
// within P ± tolerance — tested just inside and just outside both edges — and fail a variable
// that has fewer than two levels in the asymptotic range unless every level is exact to round-off.
// The studies are synthetic — the error of each level set by hand — and run through the harness's
// own study loop (norms, level rules, fit, verdict).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <vector>

#include "dlpverify/check.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/study.hpp"

namespace unit_check {

using namespace dlpverify;

namespace {

// Five levels Δt_k = 0.1 / 2^k over t_end = 1, expecting order `expected`; level k's L2 error is
// error_of(k, Δt_k) exactly. Two members: the first, reference 0, carries the error; the second,
// reference 1 and exact, gives the solution its size 1 (and so the round-off floor ½ ε √steps).
StudyResult synthetic_study(double expected, const std::function<double(int, double)>& error_of,
                            double reference_error = 0.0) {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.levels = 5;
  plan.expected_order = expected;
  plan.variables = {{"y", 0, 1, "1"}};
  int level = 0;
  const Solve solve = [&](double dt, long, SolverStatistics&) {
    State y(2, 1);
    y << error_of(level++, dt), 1.0;
    return y;
  };
  State reference(2, 1);
  reference << 0.0, 1.0;
  return run_study(plan, reference, {reference_error}, solve);
}

// Errors 1e-3 at level 0, then falling at the given pairwise orders, one a level.
StudyResult orders_study(double expected, const std::vector<double>& orders) {
  return synthetic_study(expected, [orders](int k, double) {
    double e = 1e-3;
    for (int j = 0; j < k; ++j) e /= std::pow(2.0, orders[static_cast<std::size_t>(j)]);
    return e;
  });
}

// Errors e = Δt^q exactly: the fitted order is q (to ~1e-13).
StudyResult power_law_study(double expected, double q) {
  return synthetic_study(expected, [q](int, double dt) { return std::pow(dt, q); });
}

}  // namespace

BOOST_AUTO_TEST_SUITE(check_verdict)

// P ± 0.99 tol passes, P ± 1.01 tol fails, at two orders and tolerances: the edges are |q − P| ≤ tol
// on both sides, not one side only, not a fraction or multiple of tol.
BOOST_AUTO_TEST_CASE(both_edges_of_the_tolerance) {
  for (const auto& [order, tolerance] : {std::pair{2.0, 0.1}, std::pair{4.0, 0.3}}) {
    for (double side : {+1.0, -1.0}) {
      BOOST_TEST_CONTEXT("P = " << order << ", tol = " << tolerance << ", side " << side) {
        const StudyResult inside = power_law_study(order, order + side * 0.99 * tolerance);
        BOOST_TEST(inside.orders[0].fit.value == order + side * 0.99 * tolerance, boost::test_tools::tolerance(1e-10));
        const CheckVerdict pass = check_orders(inside, order, tolerance);
        BOOST_TEST(pass.passed());
        BOOST_TEST(pass.has(CheckOutcome::order_within));

        // Below the band a lower order is seen: fail. Above it no order below P is: inconclusive.
        const StudyResult outside = power_law_study(order, order + side * 1.01 * tolerance);
        const CheckVerdict fail = check_orders(outside, order, tolerance);
        BOOST_TEST(!fail.passed());
        BOOST_TEST(fail.has(side < 0 ? CheckOutcome::order_miss : CheckOutcome::inconclusive));
      }
    }
  }
}

// A verdict's line shows why: an order just outside the band is printed to the digits that put it
// outside (4.1002, not 4.100, for 4.100179 against 4 ± 0.1: in doubles 4.100 − 4 < 0.1; 3.899821
// keeps 3.900, which 4 − 3.900 > 0.1 already puts outside); one well inside keeps three decimals.
BOOST_AUTO_TEST_CASE(the_printed_order_shows_its_side_of_the_band) {
  const CheckVerdict outside = check_orders(power_law_study(4.0, 3.899821), 4.0, 0.1);
  BOOST_TEST(!outside.passed());
  BOOST_TEST(outside.findings[0].line() == "y: FAIL, fitted order 3.900 outside 4.000 +/- 0.100 (over 5 levels)");
  const CheckVerdict above = check_orders(power_law_study(4.0, 4.100179), 4.0, 0.1);
  BOOST_TEST(above.findings[0].line().rfind("y: INCONCLUSIVE, fitted order 4.1002 above 4.000 +/- 0.100", 0) == 0,
             above.findings[0].line());
  const CheckVerdict inside = check_orders(power_law_study(4.0, 4.05), 4.0, 0.1);
  BOOST_TEST(inside.findings[0].line() == "y: pass, fitted order 4.050 within 4.000 +/- 0.100 (over 5 levels)");
}

// A variable with an order of its own (an invariant one above the method): its finding, its level
// rules and its error constant use it; without it, the same errors fail at the plan's order.
BOOST_AUTO_TEST_CASE(a_variable_expects_an_order_of_its_own) {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.levels = 5;
  plan.expected_order = 2.0;
  plan.variables = {{"y", 0, 1, "1"}, {"energy", 1, 1, "1"}};
  const Solve solve = [](double dt, long, SolverStatistics&) {
    State s(2, 2);
    s << dt * dt, dt * dt * dt, 1.0, 1.0;  // y errs at order 2, the energy at 3
    return s;
  };
  State reference(2, 2);
  reference << 0.0, 0.0, 1.0, 1.0;
  const StudyResult without = run_study(plan, reference, {0.0, 0.0}, solve);
  BOOST_TEST(!check_orders(without, 2.0, 0.1).passed());
  plan.expected_order_by_variable = {{"energy", 3.0}};
  const StudyResult study = run_study(plan, reference, {0.0, 0.0}, solve);
  const CheckVerdict verdict = check_orders(study, 2.0, 0.1);
  BOOST_TEST(verdict.passed());
  BOOST_TEST(verdict.expected_orders == (std::vector<double>{2.0, 3.0}), boost::test_tools::per_element());
  BOOST_TEST(verdict.findings[1].line() == "energy: pass, fitted order 3.000 within 3.000 +/- 0.100 (over 5 levels)");
  BOOST_TEST(study.orders[1].constant.order == 3.0);
  BOOST_TEST(study.orders[1].constant.value == 1.0, boost::test_tools::tolerance(1e-9));  // e = 1 · Δt³
  // A name that is no measured variable is refused before any level is run.
  plan.expected_order_by_variable = {{"momentum", 3.0}};
  BOOST_CHECK_EXCEPTION(run_study(plan, reference, {0.0, 0.0}, solve), InputError,
                        [](const InputError& e) { return e.quantity() == "expected order"; });
}

// One asymptotic level: the error grows under refinement into the finest level, so every coarser
// level is unstable (pre-asymptotic) and only level 4 is ok — no order was measured: FAIL.
BOOST_AUTO_TEST_CASE(one_usable_level_fails) {
  const StudyResult study = synthetic_study(2.0, [](int k, double) { return 1e-4 * (k + 1); });
  BOOST_TEST(study.orders[0].fit.levels.size() == 1u);
  BOOST_TEST(!study.orders[0].exact_to_round_off);
  const CheckVerdict verdict = check_orders(study, 2.0, 0.1);
  BOOST_TEST(!verdict.passed());
  BOOST_TEST(verdict.has(CheckOutcome::no_order));
}

// No asymptotic level, and not exact either: errors inside the round-off band (within 1000× of
// ½ ε √steps) that still fall at order 1 while order 4 is expected. Every level is round-off, but
// a method whose errors fall is never called exact; with no level above the floor double
// precision cannot decide the order: inconclusive (exit 5), never a pass.
BOOST_AUTO_TEST_CASE(falling_errors_in_the_round_off_band_do_not_pass) {
  const StudyResult study = synthetic_study(4.0, [](int, double dt) { return 1e-12 * dt; });
  BOOST_TEST(study.orders[0].fit.levels.empty());
  BOOST_TEST(!study.orders[0].exact_to_round_off);
  BOOST_TEST(study.orders[0].overall_slope == 1.0, boost::test_tools::tolerance(1e-9));
  const CheckVerdict verdict = check_orders(study, 4.0, 0.1);
  BOOST_TEST(!verdict.passed());
  BOOST_TEST(verdict.has(CheckOutcome::inconclusive));
  BOOST_TEST(verdict.exit_code() == kExitInconclusive);
}

// The contrast: zero error at every level is exact to round-off, and passes.
BOOST_AUTO_TEST_CASE(exact_at_every_level_passes) {
  const StudyResult study = synthetic_study(2.0, [](int, double) { return 0.0; });
  BOOST_TEST(study.orders[0].exact_to_round_off);
  const CheckVerdict verdict = check_orders(study, 2.0, 0.1);
  BOOST_TEST(verdict.passed());
  BOOST_TEST(verdict.has(CheckOutcome::exact));
}

// Two levels above the round-off floor fit an order with no interval: "an order needs 3". Order 2
// exactly on levels 0–1, levels 2–4 under the floor (1e-17 < ½ ε √(10·2^k)): inconclusive, and
// not a pass at order 2.000 over two levels.
BOOST_AUTO_TEST_CASE(two_levels_above_the_floor_are_no_order) {
  const StudyResult study = synthetic_study(2.0, [](int k, double dt) { return k < 2 ? 1e-2 * dt * dt : 1e-17; });
  BOOST_TEST_REQUIRE(study.orders[0].fit.levels.size() == 2u);
  const CheckVerdict verdict = check_orders(study, 2.0, 0.1);
  BOOST_TEST(verdict.inconclusive(), verdict.findings[0].line());
  BOOST_TEST(verdict.findings[0].line().find("only 2 level(s) above the round-off floor") != std::string::npos,
             verdict.findings[0].line());
}

// The same for the reference: errors 1e-5 / 16^k against a reference trusted to 1e-9 leave two
// levels at least 100 x its error (1e-5, 6.25e-7; 3.9e-8 is not): inconclusive, not a pass at 4.
BOOST_AUTO_TEST_CASE(two_levels_the_reference_trusts_are_no_order) {
  const StudyResult study = synthetic_study(4.0, [](int k, double) { return 1e-5 * std::pow(16.0, -k); }, 1e-9);
  BOOST_TEST_REQUIRE(study.orders[0].fit.levels.size() == 2u);
  const CheckVerdict verdict = check_orders(study, 4.0, 0.1);
  BOOST_TEST(verdict.inconclusive(), verdict.findings[0].line());
  BOOST_TEST(verdict.findings[0].line().find("only 2 level(s) with an error at least 100 x the reference") !=
                 std::string::npos,
             verdict.findings[0].line());
}

// "Keep moving away over the finest three" needs both steps to move away. Finest orders 1.99,
// 1.95, 1.96: the first step away, the second back (|p − 2| = 0.01, 0.05, 0.04): a pass at 2 ± 0.1.
// Finest orders 1.995, 1.988, 1.981, each step under a tenth of the band but 0.014 in all, both
// away: inconclusive.
BOOST_AUTO_TEST_CASE(moving_away_needs_both_steps) {
  const CheckVerdict back = check_orders(orders_study(2.0, {2.0, 1.99, 1.95, 1.96}), 2.0, 0.1);
  BOOST_TEST(back.passed(), back.findings[0].line());
  const CheckVerdict away = check_orders(orders_study(2.0, {2.0, 1.995, 1.988, 1.981}), 2.0, 0.1);
  BOOST_TEST(away.inconclusive(), away.findings[0].line());
  BOOST_TEST(away.findings[0].line().find("keep moving away") != std::string::npos, away.findings[0].line());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_check
