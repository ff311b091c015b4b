// Observed order of accuracy (docs/model.md §6): the least-squares fit and the level rules of analyse_order.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <ostream>
#include <vector>

#include "dlpverify/order.hpp"

namespace dlpverify {
// So BOOST_TEST can print a status (internal linkage: other test files may define their own).
static std::ostream& operator<<(std::ostream& out, LevelStatus status) { return out << to_string(status); }
}  // namespace dlpverify

namespace unit_order_fit {

using namespace dlpverify;
namespace tt = boost::test_tools;

namespace {
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Student t quantile t_{0.975, 3} (three degrees of freedom: five levels minus two parameters).
constexpr double kStudent975Dof3 = 3.182446305284263;

// Δt_k = 0.1 / 2^k, k = 0 … n−1.
std::vector<double> steps_of(int n) {
  std::vector<double> dt;
  for (int k = 0; k < n; ++k) dt.push_back(0.1 / std::pow(2.0, k));
  return dt;
}

std::vector<int> all_levels(int n) {
  std::vector<int> levels;
  for (int k = 0; k < n; ++k) levels.push_back(k);
  return levels;
}

// Levels with Δt_k = 0.1 / 2^k, 10·2^k steps (t_end = 1), the given errors and solution size.
std::vector<LevelErrors> levels_with(const std::vector<double>& errors, double solution_size = 1.0) {
  std::vector<LevelErrors> levels;
  for (std::size_t k = 0; k < errors.size(); ++k)
    levels.push_back({0.1 / std::pow(2.0, static_cast<double>(k)), 10L << k, errors[k], solution_size});
  return levels;
}

OrderRules rules_expecting(double order) {
  OrderRules rules;
  rules.expected_order = order;
  return rules;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(order_fit)

// e = C Δt^p exactly: the slope is p, the residuals (and so the standard error) vanish.
BOOST_AUTO_TEST_CASE(exact_power_law) {
  const std::vector<double> dt = steps_of(5);
  for (double p : {1.0, 2.0, 4.0, 6.0}) {
    std::vector<double> error;
    for (double h : dt) error.push_back(3.7 * std::pow(h, p));
    const OrderFit fit = fit_order(dt, error, all_levels(5));
    BOOST_TEST(fit.valid);
    BOOST_TEST(std::abs(fit.value - p) <= 1e-12, "p = " << p << ": " << fit.value);
    BOOST_TEST(fit.stderr_ <= 1e-12);
    BOOST_TEST(fit.ci_low <= fit.value);
    BOOST_TEST(fit.ci_high >= fit.value);
    BOOST_TEST(fit.levels == all_levels(5), tt::per_element());
  }
}

// ln e_k = ln C + p ln Δt_k + δ (−1)^k, k = 0 … 4. By hand: x_k = ln Δt_k = x_0 − k ln 2, so
// x_k − x̄ = −(k − 2) ln 2 and Sxx = 10 ln²2. The noise is orthogonal to x − x̄
// (Σ (k − 2)(−1)^k = −2 + 1 + 0 − 1 + 2 = 0), so the slope is exactly p; its mean δ/5 goes into the
// intercept and the residuals are δ (−1)^k − δ/5: SSR = δ² (3 · (4/5)² + 2 · (6/5)²) = 4.8 δ².
// Standard error = √(SSR / (n − 2) / Sxx) = √(1.6 δ² / (10 ln²2)) = 0.4 δ / ln 2.
// 95% half-width = t_{0.975, 3} · stderr.
BOOST_AUTO_TEST_CASE(alternating_noise) {
  const std::vector<double> dt = steps_of(5);
  const double p = 2.0, delta = 0.01;
  std::vector<double> error;
  for (int k = 0; k < 5; ++k) error.push_back(3.7 * std::pow(dt[k], p) * std::exp(delta * (k % 2 == 0 ? 1.0 : -1.0)));
  const OrderFit fit = fit_order(dt, error, all_levels(5));

  // The same OLS, computed here term by term.
  double x_mean = 0.0, y_mean = 0.0;
  for (int k = 0; k < 5; ++k) {
    x_mean += std::log(dt[k]) / 5.0;
    y_mean += std::log(error[k]) / 5.0;
  }
  double sxx = 0.0, sxy = 0.0;
  for (int k = 0; k < 5; ++k) {
    sxx += (std::log(dt[k]) - x_mean) * (std::log(dt[k]) - x_mean);
    sxy += (std::log(dt[k]) - x_mean) * (std::log(error[k]) - y_mean);
  }
  const double slope = sxy / sxx, intercept = y_mean - slope * x_mean;
  double ssr = 0.0;
  for (int k = 0; k < 5; ++k) {
    const double r = std::log(error[k]) - intercept - slope * std::log(dt[k]);
    ssr += r * r;
  }
  const double stderr_by_hand = std::sqrt(ssr / 3.0 / sxx);
  const double stderr_closed_form = 0.4 * delta / std::log(2.0);

  BOOST_TEST(stderr_by_hand == stderr_closed_form, tt::tolerance(1e-10));
  BOOST_TEST(std::abs(fit.value - p) <= 1e-12);
  BOOST_TEST(fit.stderr_ == stderr_closed_form, tt::tolerance(1e-10));
  BOOST_TEST(fit.ci_high - fit.value == kStudent975Dof3 * stderr_closed_form, tt::tolerance(1e-9));
  BOOST_TEST(fit.value - fit.ci_low == kStudent975Dof3 * stderr_closed_form, tt::tolerance(1e-9));
}

// One level alone perturbed: ln e_k = ln C + p ln Δt_k + δ [k = 1]. By hand, with x_k − x̄ = −(k − 2) ln 2
// and Sxx = 10 ln²2 as above: slope = p + δ (x_1 − x̄) / Sxx = p + δ / (10 ln 2). The residuals are
// δ [k = 1] − δ/5 + δ (k − 2)/10 = (−0.4, 0.7, −0.2, −0.1, 0) δ, so SSR = 0.7 δ² and the standard
// error is √(0.7 δ² / 3 / (10 ln²2)) = δ √(7/300) / ln 2. A slope from the first and last levels
// alone would be exactly p, and would pass the tests above: this one tells them apart.
BOOST_AUTO_TEST_CASE(one_level_perturbed) {
  const std::vector<double> dt = steps_of(5);
  const double p = 2.0, delta = 0.3;
  std::vector<double> error;
  for (int k = 0; k < 5; ++k) error.push_back(3.7 * std::pow(dt[k], p) * (k == 1 ? std::exp(delta) : 1.0));
  const double slope_by_hand = p + delta / (10.0 * std::log(2.0));  // 2.0432809…
  const double stderr_by_hand = delta * std::sqrt(7.0 / 300.0) / std::log(2.0);

  const OrderFit fit = fit_order(dt, error, all_levels(5));
  BOOST_TEST(fit.value == slope_by_hand, tt::tolerance(1e-12));
  BOOST_TEST(fit.stderr_ == stderr_by_hand, tt::tolerance(1e-10));
  BOOST_TEST(std::abs(fit.value - p) > 0.04);  // not the first-to-last slope

  // The same through the level rules: the perturbation bends the coarse pairwise orders (2.43,
  // 1.57, then 2 and 2), so levels 0 and 1 leave the window as pre-asymptotic (each order further
  // from the finer levels' than the next one) and levels 2–4 fit p exactly.
  const OrderAnalysis a = analyse_order(levels_with(error), rules_expecting(2.0));
  BOOST_TEST(a.status[0] == LevelStatus::pre_asymptotic);
  BOOST_TEST(a.status[1] == LevelStatus::pre_asymptotic);
  BOOST_TEST(a.fit.levels == std::vector<int>({2, 3, 4}), tt::per_element());
  BOOST_TEST(a.fit.value == p, tt::tolerance(1e-12));
}

// Two levels: a slope, but no residual degree of freedom, so no standard error or interval.
// One level: no fit at all. A subset of levels fits only those levels.
BOOST_AUTO_TEST_CASE(few_levels) {
  const std::vector<double> dt = steps_of(5);
  std::vector<double> error;
  for (double h : dt) error.push_back(2.0 * h * h);
  const OrderFit two = fit_order(dt, error, {1, 3});
  BOOST_TEST(two.valid);
  BOOST_TEST(std::abs(two.value - 2.0) <= 1e-12);
  BOOST_TEST(std::isnan(two.stderr_));
  BOOST_TEST(std::isnan(two.ci_low));
  BOOST_TEST(std::isnan(two.ci_high));

  const OrderFit one = fit_order(dt, error, {2});
  BOOST_TEST(!one.valid);

  // Levels 0 and 1 are garbage; fitting levels 2–4 only must ignore them.
  error[0] = 1.0;
  error[1] = 1e-9;
  const OrderFit subset = fit_order(dt, error, {2, 3, 4});
  BOOST_TEST(std::abs(subset.value - 2.0) <= 1e-12);
  BOOST_TEST(subset.levels == std::vector<int>({2, 3, 4}), tt::per_element());
}

// docs/model.md §6 round-off floor, as order.hpp defines it: ½ ε √steps ‖y‖.
BOOST_AUTO_TEST_CASE(round_off_floor_formula) {
  BOOST_TEST(round_off_floor({0.0125, 80, 0.0, 2.5}) == 0.5 * kEpsilon * std::sqrt(80.0) * 2.5);
  BOOST_TEST(round_off_floor({0.1, 0, 0.0, 1.0}) == 0.5 * kEpsilon);  // at least one step
  BOOST_TEST(round_off_floor({0.1, 10, 0.0, 0.0}) > 0.0);             // a zero solution still has a floor
}

// Second order down to level 2, then the error falls to the floor at level 3 (1e-20 ≤ ½ ε √80).
// Level 4 is under its floor too. The fit uses levels 0–2: slope 2.
BOOST_AUTO_TEST_CASE(level_at_floor_is_round_off) {
  const OrderAnalysis a = analyse_order(levels_with({1e-4, 2.5e-5, 6.25e-6, 1e-20, 3e-20}), rules_expecting(2.0));
  BOOST_TEST(a.status[0] == LevelStatus::ok);
  BOOST_TEST(a.status[1] == LevelStatus::ok);
  BOOST_TEST(a.status[2] == LevelStatus::ok);
  BOOST_TEST(a.status[3] == LevelStatus::round_off);
  BOOST_TEST(a.status[4] == LevelStatus::round_off);
  BOOST_TEST(!a.exact_to_round_off);
  BOOST_TEST(a.floor[3] == 0.5 * kEpsilon * std::sqrt(80.0));
  BOOST_TEST(!a.pairwise[0].has_value());
  BOOST_TEST(*a.pairwise[1] == 2.0, tt::tolerance(1e-12));  // ln 4 / ln 2
  BOOST_TEST(a.fit.levels == std::vector<int>({0, 1, 2}), tt::per_element());
  BOOST_TEST(std::abs(a.fit.value - 2.0) <= 1e-12);

  // The floor is inclusive: an error equal to ½ ε √steps ‖y‖ is round-off; just above it is not
  // (no expected order here, so no rate rule).
  const double floor3 = 0.5 * kEpsilon * std::sqrt(80.0);
  const OrderAnalysis at = analyse_order(levels_with({1e-4, 2.5e-5, 6.25e-6, floor3}), OrderRules{});
  BOOST_TEST(at.status[3] == LevelStatus::round_off);
  const OrderAnalysis above = analyse_order(levels_with({1e-4, 2.5e-5, 6.25e-6, 1.01 * floor3}), OrderRules{});
  BOOST_TEST(above.status[3] == LevelStatus::ok);
}

// A NaN error is unstable and left out; the other levels are fitted.
BOOST_AUTO_TEST_CASE(nan_is_unstable) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const OrderAnalysis a = analyse_order(levels_with({1e-4, nan, 6.25e-6, 1.5625e-6}), rules_expecting(2.0));
  BOOST_TEST(a.status[0] == LevelStatus::ok);
  BOOST_TEST(a.status[1] == LevelStatus::unstable);
  BOOST_TEST(a.status[2] == LevelStatus::ok);
  BOOST_TEST(a.status[3] == LevelStatus::ok);
  BOOST_TEST(a.fit.levels == std::vector<int>({0, 2, 3}), tt::per_element());
  BOOST_TEST(std::abs(a.fit.value - 2.0) <= 1e-12);
}

// An error that grows under refinement flags every coarser level unstable (pre-asymptotic); the
// fit starts where refinement reduces the error.
BOOST_AUTO_TEST_CASE(growth_flags_coarser_levels) {
  const OrderAnalysis first = analyse_order(levels_with({1e-2, 4e-2, 1e-2, 2.5e-3, 6.25e-4}), rules_expecting(2.0));
  BOOST_TEST(first.status[0] == LevelStatus::unstable);
  for (int k = 1; k < 5; ++k) BOOST_TEST(first.status[k] == LevelStatus::ok, "level " << k);
  BOOST_TEST(first.fit.levels == std::vector<int>({1, 2, 3, 4}), tt::per_element());
  BOOST_TEST(std::abs(first.fit.value - 2.0) <= 1e-12);

  const OrderAnalysis middle = analyse_order(levels_with({1e-3, 2.5e-4, 5e-4, 1.25e-4, 3.125e-5}), rules_expecting(2.0));
  BOOST_TEST(middle.status[0] == LevelStatus::unstable);
  BOOST_TEST(middle.status[1] == LevelStatus::unstable);
  BOOST_TEST(middle.status[2] == LevelStatus::ok);
  BOOST_TEST(middle.fit.levels == std::vector<int>({2, 3, 4}), tt::per_element());

  // An error as large as the solution itself is unstable too.
  const OrderAnalysis huge = analyse_order(levels_with({2.0, 1e-2, 2.5e-3}), rules_expecting(2.0));
  BOOST_TEST(huge.status[0] == LevelStatus::unstable);
}

// docs/model.md §6: "the similarity and gravity cases are exact for RK2: every level sits at the floor".
BOOST_AUTO_TEST_CASE(all_at_floor_is_exact_to_round_off) {
  const OrderAnalysis zero = analyse_order(levels_with({0.0, 0.0, 0.0, 0.0}), rules_expecting(2.0));
  BOOST_TEST(zero.exact_to_round_off);
  BOOST_TEST(!zero.fit.valid);
  for (int k = 0; k < 4; ++k) BOOST_TEST(zero.status[k] == LevelStatus::round_off);

  // Errors of about one ε relative: levels 0 and 2–3 under their floors ½ ε √(10·2^k), level 1
  // just above its own but within 1000× of it and finer than a round-off level.
  const OrderAnalysis tiny = analyse_order(levels_with({3e-16, 5e-16, 4e-16, 9e-16}), rules_expecting(2.0));
  BOOST_TEST(tiny.exact_to_round_off);
  BOOST_TEST(!tiny.fit.valid);

  // Recorded: RK4 on the gravity case, relative L2 velocity error at 20…320 steps (R_out 10).
  // Level 0 (10.6 ε) is above its floor (2.2 ε) and has no incoming order, but the error does not
  // fall to level 1, so it is round-off; the rest are finer and within the band. Errors grow under
  // refinement (overall slope < 0): the method is exact.
  std::vector<LevelErrors> gravity;
  const std::vector<double> recorded{2.35e-15, 3.30e-15, 3.20e-15, 2.71e-15, 2.45e-14};
  for (int k = 0; k < 5; ++k) gravity.push_back({5e-4 / std::pow(2.0, k), 20L << k, recorded[k], 1.0});
  const OrderAnalysis g = analyse_order(gravity, rules_expecting(4.0));
  for (int k = 0; k < 5; ++k) BOOST_TEST(g.status[k] == LevelStatus::round_off, "level " << k);
  BOOST_TEST(g.overall_slope < 0.0);
  BOOST_TEST(g.exact_to_round_off);
}

// Errors that keep falling are never "exact", however close to the floor: an order-1 method
// checked against order 4 with errors inside the band is round-off level by level, but its errors
// fall at order 1 over all levels, so it is not exact and has no fitted order (check fails).
BOOST_AUTO_TEST_CASE(falling_errors_are_never_exact) {
  const OrderAnalysis a = analyse_order(levels_with({1e-13, 5e-14, 2.5e-14, 1.25e-14}), rules_expecting(4.0));
  BOOST_TEST(a.overall_slope == 1.0, tt::tolerance(1e-12));
  BOOST_TEST(!a.exact_to_round_off);
  BOOST_TEST(!a.fit.valid);
}

// docs/model.md §6: a level near the floor whose pairwise order collapses is round-off. Expected order 6,
// rate_drop_fraction 0.75: threshold 4.5. Levels 0–2 fall at exactly order 6 (×1/64); level 3 falls
// only by 8 (order 3 < 4.5) to 1e-13, within 1000× of its floor ½ ε √80 = 9.93e-16. Level 4
// (9e-14, within 1000× of its floor 1.40e-15) is finer than a round-off level, so round-off too.
BOOST_AUTO_TEST_CASE(rate_collapse_near_floor_is_round_off) {
  const std::vector<double> errors{3.2768e-9, 5.12e-11, 8e-13, 1e-13, 9e-14};
  const OrderAnalysis a = analyse_order(levels_with(errors), rules_expecting(6.0));
  BOOST_TEST(*a.pairwise[2] == 6.0, tt::tolerance(1e-12));
  BOOST_TEST(*a.pairwise[3] == 3.0, tt::tolerance(1e-12));
  BOOST_TEST(a.status[0] == LevelStatus::ok);
  BOOST_TEST(a.status[1] == LevelStatus::ok);
  BOOST_TEST(a.status[2] == LevelStatus::ok);
  BOOST_TEST(a.status[3] == LevelStatus::round_off);
  BOOST_TEST(a.status[4] == LevelStatus::round_off);
  BOOST_TEST(!a.exact_to_round_off);
  BOOST_TEST(a.fit.levels == std::vector<int>({0, 1, 2}), tt::per_element());
  BOOST_TEST(std::abs(a.fit.value - 6.0) <= 1e-12);

  // Without an expected order there is no rate-drop rule: every level is used.
  const OrderAnalysis unknown = analyse_order(levels_with(errors), rules_expecting(0.0));
  for (int k = 0; k < 5; ++k) BOOST_TEST(unknown.status[k] == LevelStatus::ok, "level " << k);

  // The same collapse far from the floor (solution 1e-3: floors 1000× lower) is not round-off.
  const OrderAnalysis far = analyse_order(levels_with(errors, 1e-3), rules_expecting(6.0));
  BOOST_TEST(far.status[3] == LevelStatus::ok);
  BOOST_TEST(far.fit.levels.size() == 5u);
}

// Recorded: ARKODE's Verner 6th-order table on drag (R_out 6, Δt 5e-4…3.125e-5, relative L2
// velocity error). Level 3 (12.5 ε‖v‖) is near its floor but still converging at order 6.16 ≥ 4.5:
// it stays in the fit. Level 4 falls at order 0.87: round-off. Level 0's order to level 1, 6.28,
// is 0.13 from the finer levels' 6.15 (level 1's 6.15 is closer): pre-asymptotic.
BOOST_AUTO_TEST_CASE(converging_level_near_floor_stays_in_fit) {
  const std::vector<double> recorded{1.097e-9, 1.408e-11, 1.987e-13, 2.782e-15, 1.522e-15};
  std::vector<LevelErrors> verner;
  for (int k = 0; k < 5; ++k) verner.push_back({5e-4 / std::pow(2.0, k), 20L << k, recorded[k], 1.0});
  const OrderAnalysis a = analyse_order(verner, rules_expecting(6.0));
  BOOST_TEST(a.status[0] == LevelStatus::pre_asymptotic);
  for (int k = 1; k < 4; ++k) BOOST_TEST(a.status[k] == LevelStatus::ok, "level " << k);
  BOOST_TEST(a.status[4] == LevelStatus::round_off);
  BOOST_TEST(a.fit.levels == std::vector<int>({1, 2, 3}), tt::per_element());
}

BOOST_AUTO_TEST_SUITE_END()

// docs/model.md §6, reference-free: levels y_k = y* + C Δt_k^p with Δt_k = Δt_0 / r^k give differences
// d_k = C Δt_k^p (r^p − 1), so the self-convergence order is p, Richardson's estimate of the finest
// error is exactly C Δt_finest^p, and GCI = 1.25 · that / |y|.
BOOST_AUTO_TEST_SUITE(self_convergence)

BOOST_AUTO_TEST_CASE(power_law_levels) {
  const double C = 3.0, p = 2.0, r = 2.0, dt0 = 0.1, size = 10.0;
  std::vector<double> y;
  for (int k = 0; k < 5; ++k) y.push_back(1.0 + C * std::pow(dt0 / std::pow(r, k), p));
  std::vector<std::optional<double>> d{std::nullopt};
  for (int k = 1; k < 5; ++k) d.push_back(std::abs(y[k - 1] - y[k]));
  const SelfConvergence s = analyse_self_convergence(d, size, r);
  BOOST_TEST(!s.order[0].has_value());
  BOOST_TEST(!s.order[1].has_value());
  for (int k = 2; k < 5; ++k) BOOST_TEST(*s.order[k] == p, tt::tolerance(1e-9));
  const double finest_error = C * std::pow(dt0 / std::pow(r, 4), p);
  BOOST_TEST(*s.richardson_error == finest_error, tt::tolerance(1e-9));
  BOOST_TEST(*s.gci == kGciSafetyFactor * finest_error / size, tt::tolerance(1e-9));
}

// Differences that grow under refinement give a negative order and no estimate.
BOOST_AUTO_TEST_CASE(diverging_levels_have_no_estimate) {
  const SelfConvergence s = analyse_self_convergence({std::nullopt, 1e-3, 2e-3, 4e-3}, 1.0, 2.0);
  BOOST_TEST(*s.order[3] < 0.0);
  BOOST_TEST(!s.richardson_error.has_value());
  BOOST_TEST(!s.gci.has_value());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_order_fit
