// The error constant C of e ≈ C Δt^p (dlpverify/error_constant.hpp): on synthetic errors, where C
// and its interval follow by hand, and through whole studies of y' = −y², whose global error has a
// leading term in closed form for every two-stage method of order 2 and for explicit Euler.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <utility>
#include <vector>

#include "quadratic_decay.hpp"
#include "dlpverify/error_constant.hpp"
#include "dlpverify/order.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/study.hpp"

namespace unit_error_constant {

using namespace dlpverify;

namespace {

using Quadratic = test::QuadraticDecay;

template <class Method>
ErrorConstant study_constant(Method& method, double expected_order) {
  const Quadratic problem;
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 1.0 / 64.0;
  plan.levels = 5;  // Δt = 1/64 … 1/1024
  plan.expected_order = expected_order;
  const StudyResult study = run_study(problem, method, plan);
  BOOST_REQUIRE(study.orders.size() == 1u);
  return study.orders[0].constant;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(error_constant)

// e_k = C Δt_k^p exactly: every ln C_k is ln C, so the interval closes on C.
BOOST_AUTO_TEST_CASE(exact_power_law_gives_its_constant) {
  const std::vector<double> dt{0.1, 0.05, 0.025, 0.0125};
  std::vector<double> error;
  for (double h : dt) error.push_back(3.5 * h * h);
  const ErrorConstant c = fit_error_constant(dt, error, {0, 1, 2, 3}, 2.0);
  BOOST_REQUIRE(c.valid);
  BOOST_TEST(std::abs(c.value / 3.5 - 1.0) < 1e-14);
  BOOST_TEST(std::abs(c.ci_low / 3.5 - 1.0) < 1e-12);
  BOOST_TEST(std::abs(c.ci_high / 3.5 - 1.0) < 1e-12);
  BOOST_TEST(c.order == 2.0);
  BOOST_TEST((c.levels == std::vector<int>{0, 1, 2, 3}));
}

// ln C_k = ln C ± δ alternately over n = 4 levels: the mean is ln C, s = √(4δ²/3), s/√n = δ/√3,
// and the interval is C exp(± t₀.₉₇₅,₃ δ/√3) with t₀.₉₇₅,₃ = 3.182446305284263 (Student's t).
BOOST_AUTO_TEST_CASE(scatter_gives_students_interval) {
  const double delta = 0.02, C = 0.7;
  const std::vector<double> dt{0.2, 0.1, 0.05, 0.025};
  std::vector<double> error;
  for (std::size_t k = 0; k < dt.size(); ++k) error.push_back(C * std::exp(k % 2 ? -delta : delta) * std::pow(dt[k], 3.0));
  const ErrorConstant c = fit_error_constant(dt, error, {0, 1, 2, 3}, 3.0);
  BOOST_REQUIRE(c.valid);
  BOOST_TEST(std::abs(c.value / C - 1.0) < 1e-13);
  BOOST_TEST(std::abs(c.log_stderr - delta / std::sqrt(3.0)) < 1e-13);
  const double half = 3.182446305284263 * delta / std::sqrt(3.0);
  BOOST_TEST(std::abs(c.ci_low / (C * std::exp(-half)) - 1.0) < 1e-12);
  BOOST_TEST(std::abs(c.ci_high / (C * std::exp(half)) - 1.0) < 1e-12);
}

// Only the listed levels count; one level has no interval; none, or an unknown order, no constant.
BOOST_AUTO_TEST_CASE(levels_and_edge_cases) {
  const std::vector<double> dt{0.1, 0.05, 0.025};
  const std::vector<double> error{1.0, 2.0 * 0.05 * 0.05, 2.0 * 0.025 * 0.025};  // level 0 off the line
  const ErrorConstant two = fit_error_constant(dt, error, {1, 2}, 2.0);
  BOOST_TEST(std::abs(two.value / 2.0 - 1.0) < 1e-14);
  const ErrorConstant one = fit_error_constant(dt, error, {2}, 2.0);
  BOOST_TEST(one.valid);
  BOOST_TEST(std::abs(one.value / 2.0 - 1.0) < 1e-14);
  BOOST_TEST(std::isnan(one.ci_low));
  BOOST_TEST(!fit_error_constant(dt, error, {}, 2.0).valid);
  BOOST_TEST(!fit_error_constant(dt, error, {1, 2}, 0.0).valid);
  BOOST_TEST(!fit_error_constant(dt, {1.0, 0.0, 1e-3}, {1, 2}, 2.0).valid);
}

// y' = −y², y(0) = 1, to T = 1. The global error of a method with local error −ψ(y) Δt^(p+1) is
// Δt^p ∫₀ᵀ Φ(T, s) ψ(y(s)) ds with Φ(T, s) = ((1 + s)/(1 + T))² (f_y = −2y = −2/(1 + t)).
// Two-stage order 2 (c₂ = α, b₂ = 1/(2α)): ψ = (1/6 − α/4) f_yy f² + (1/6) f_y² f = −(3/4) y⁴ for
// the midpoint rule (α = ½), −(1/2) y⁴ for Heun (α = 1), so |C| = (3/4 or 1/2) T/(1 + T)³ =
// 3/32 and 1/16: 1.5 times apart. Explicit Euler: ψ = −½ f_y f = −y³, |C| = ln(1 + T)/(1 + T)² =
// ln 2/4. The fitted C over Δt = 1/64 … 1/1024 carries the next term, O(Δt) relative: measured
// within 0.8% (midpoint +0.76%, Heun +0.45%, Euler +0.31%; the same arithmetic in Python gives the
// same), asserted within 1.5%.
BOOST_AUTO_TEST_CASE(closed_form_constants_of_euler_midpoint_and_heun) {
  ExplicitRungeKutta<tableau::euler> euler("euler");
  ExplicitRungeKutta<tableau::midpoint> midpoint("midpoint");
  ExplicitRungeKutta<tableau::heun> heun("heun");
  const ErrorConstant e = study_constant(euler, 1.0), m = study_constant(midpoint, 2.0), h = study_constant(heun, 2.0);
  BOOST_REQUIRE(e.valid && m.valid && h.valid);
  BOOST_TEST(std::abs(e.value / (std::log(2.0) / 4.0) - 1.0) < 0.015, "Euler C = " << e.value);
  BOOST_TEST(std::abs(m.value / (3.0 / 32.0) - 1.0) < 0.015, "midpoint C = " << m.value);
  BOOST_TEST(std::abs(h.value / (1.0 / 16.0) - 1.0) < 0.015, "Heun C = " << h.value);
  BOOST_TEST((m.levels == std::vector<int>{0, 1, 2, 3, 4}));
}

// Euler expected at order 2 fits order 1: its constant is fitted at 1, the order its errors show,
// and is the closed form's ln 2/4 (at 2, e_k/Δt_k² would double from level to level).
BOOST_AUTO_TEST_CASE(a_method_off_its_order_gets_the_constant_of_its_fitted_order) {
  ExplicitRungeKutta<tableau::euler> euler("euler");
  const ErrorConstant e = study_constant(euler, 2.0);
  BOOST_REQUIRE(e.valid);
  BOOST_TEST(e.order == 1.0);
  BOOST_TEST(std::abs(e.value / (std::log(2.0) / 4.0) - 1.0) < 0.015, "Euler C = " << e.value);
}

// P while the fitted order lies within ½ of it (or there is no fit), the nearest integer beyond.
BOOST_AUTO_TEST_CASE(constant_order_at_the_half_way_edges) {
  OrderFit fit;
  fit.valid = true;
  for (const auto& [fitted, order] : std::vector<std::pair<double, double>>{
           {2.5, 2.0}, {1.5, 2.0}, {1.4999, 1.0}, {2.5001, 3.0}, {1.009, 1.0}, {4.023, 4.0}, {0.4, 0.0}}) {
    fit.value = fitted;
    BOOST_TEST(error_constant_order(fit, 2.0) == order, "fitted " << fitted);
  }
  fit.valid = false;
  fit.value = 1.0;
  BOOST_TEST(error_constant_order(fit, 2.0) == 2.0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_error_constant
