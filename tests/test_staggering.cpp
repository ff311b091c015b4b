// Staggered backward Euler and the seed's Algorithm 7.1 (src/integrators/implicit) on the coupled systems of
// docs/model.md §7.3 (src/problems/thermal/coupled.hpp):
//   - the measured contraction per sweep equals the spectral radius to 1e-6 at three steps, for
//     Jacobi (Δt/√(ab), (Δt⁴/|abc|)^{1/3}, the seed's) and Gauss–Seidel (their squares and 3/2
//     powers, worked out by hand for these cyclic couplings), and a step above the limit diverges;
//   - the converged 2 × 2 step equals the backward-Euler step solved by hand (Cramer's rule);
//   - the 3 × 3 closed form (a matrix exponential) against an independent RK4 integration;
//   - Algorithm 7.1 from a step above the limit: every accepted step below √(ab), the error at the
//     end within 10 × TOL and falling with TOL, and the Table 7.1 counts.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "dlpverify/closed_form.hpp"
#include "integrators/implicit/adaptive.hpp"
#include "integrators/implicit/staggered_solver.hpp"
#include "problems/thermal/coupled.hpp"

namespace unit_staggering {

using namespace dlpverify;
using namespace dlpverify::implicit;
using thermal::CoupledSystem;

namespace {

StaggeredIteration one_step(const CoupledSystem& system, Sweep sweep, double dt, State& w) {
  StaggeredSolver solver(system, sweep, system.initial_state());
  return solver.step(system.initial_state(), 0.0, dt, std::vector<double>(solver.blocks().size(), 1e-14), 2000, w);
}

double relative(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

}  // namespace

BOOST_AUTO_TEST_SUITE(staggering)

BOOST_AUTO_TEST_CASE(contraction_is_the_spectral_radius) {
  const CoupledSystem pair("stagger-2x2", 2, {2.0, 0.5, 1.0});     // √(ab) = 1
  const CoupledSystem triple("stagger-3x3", 3, {2.0, 0.5, 1.0});   // |abc| = 1
  State w;
  for (double dt : {0.3, 0.6, 0.9}) {
    BOOST_TEST_CONTEXT("dt " << dt) {
      BOOST_TEST(relative(one_step(pair, Sweep::jacobi, dt, w).contraction, dt) < 1e-6);
      BOOST_TEST(relative(one_step(pair, Sweep::gauss_seidel, dt, w).contraction, dt * dt) < 1e-6);
      BOOST_TEST(relative(one_step(triple, Sweep::jacobi, dt, w).contraction, std::cbrt(std::pow(dt, 4))) < 1e-6);
      BOOST_TEST(relative(one_step(triple, Sweep::gauss_seidel, dt, w).contraction, dt * dt) < 1e-6);
    }
  }
  const StaggeredIteration above = one_step(pair, Sweep::jacobi, 1.2, w);
  BOOST_TEST(above.diverged);
  BOOST_TEST(!above.converged);
  BOOST_TEST(relative(above.contraction, 1.2) < 1e-6);
  BOOST_TEST(one_step(triple, Sweep::gauss_seidel, 1.1, w).diverged);
}

BOOST_AUTO_TEST_CASE(converged_step_is_backward_euler) {
  // w1 + (Δt/a) w2 = w1⁰, w2 + (Δt/b) w1 = w2⁰: w1 = (ab w1⁰ − bΔt w2⁰)/(ab − Δt²), and symmetrically.
  const double a = 2.0, b = 0.5, dt = 0.7;
  const CoupledSystem pair("stagger-2x2", 2, {a, b, 1.0});
  const State y = pair.initial_state();
  State w;
  BOOST_TEST(one_step(pair, Sweep::gauss_seidel, dt, w).converged);
  for (Eigen::Index k = 0; k < y.rows(); ++k) {
    const double w1 = (a * b * y(k, 0) - b * dt * y(k, 1)) / (a * b - dt * dt);
    const double w2 = (a * b * y(k, 1) - a * dt * y(k, 0)) / (a * b - dt * dt);
    BOOST_TEST(std::abs(w(k, 0) - w1) < 1e-13);
    BOOST_TEST(std::abs(w(k, 1) - w2) < 1e-13);
  }
}

BOOST_AUTO_TEST_CASE(three_by_three_closed_form_against_rk4) {
  const CoupledSystem triple("stagger-3x3", 3, {2.0, 0.5, 1.0});
  const State y0 = triple.initial_state();
  const State exact = closed_form(triple, y0, 1.0);
  const int n = 4000;
  const double h = 1.0 / n;
  for (Eigen::Index k = 0; k < y0.rows(); ++k) {
    Eigen::Vector4d y = y0.row(k).transpose();
    auto f = [](const Eigen::Vector4d& v) { return Eigen::Vector4d(-v(1) / 2.0, -v(2) / 0.5, v(3), -v(0) / 1.0); };
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector4d k1 = f(y), k2 = f(y + 0.5 * h * k1), k3 = f(y + 0.5 * h * k2), k4 = f(y + h * k3);
      y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    for (int c = 0; c < 4; ++c) BOOST_TEST(std::abs(exact(k, c) - y(c)) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(adaptive_run_from_above_the_limit) {
  const CoupledSystem pair("stagger-2x2", 2, {2.0, 0.5, 1.0});
  const State y0 = pair.initial_state();
  const State exact = closed_form(pair, y0, 1.0);
  double previous_error = INFINITY;
  for (double tol : {1e-3, 1e-4}) {
    BOOST_TEST_CONTEXT("TOL " << tol) {
      AdaptiveSettings s;
      s.tolerance = {tol, tol};
      s.error_tolerance = tol;
      const AdaptiveRun run = run_adaptive(pair, y0, 0.0, 1.0, 1.5, s);
      BOOST_TEST(run.largest_step < pair.step_limit());
      BOOST_TEST(run.rejected_staggering >= 1);  // the first try, at 1.5, cannot converge
      BOOST_TEST(run.accepted > 0);
      BOOST_TEST(run.sweeps > run.accepted);
      double error = 0.0;
      for (Eigen::Index k = 0; k < y0.rows(); ++k)
        error = std::max(error, (run.state.row(k) - exact.row(k)).matrix().norm() / exact.row(k).matrix().norm());
      BOOST_TEST(error <= 10.0 * tol);
      BOOST_TEST(error < previous_error);
      previous_error = error;
    }
  }
}

BOOST_AUTO_TEST_CASE(document_control_alone_stays_below_the_limit) {
  // Without the local-error bound the step follows the sweep count alone: K_d = 10 sweeps to
  // TOL = 1e-6 aim at ρ ≈ 10^(−6/10) ≈ 0.25 per sweep, well below the limit.
  const CoupledSystem pair("stagger-2x2", 2, {2.0, 0.5, 1.0});
  AdaptiveSettings s;
  s.tolerance = {1e-6, 1e-6};
  const AdaptiveRun run = run_adaptive(pair, pair.initial_state(), 0.0, 5.0, 1.5, s);
  BOOST_TEST(run.largest_step < pair.step_limit());
  BOOST_TEST(run.largest_step > 0.1);
  BOOST_TEST(run.rejected_staggering >= 1);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_staggering
