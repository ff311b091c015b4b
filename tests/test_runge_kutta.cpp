// The fixed-step explicit Runge–Kutta family of docs/model.md §3: single steps against hand formulas, the
// observed order of the local error of each tableau, and ExplicitRungeKutta::advance on a tiny cloud.
#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "problems/dlp/exact/drag.hpp"
#include "integrators/registry.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "problems/dlp/cloud.hpp"
#include "problems/dlp/rates.hpp"
#include "dlp_support.hpp"

namespace unit_runge_kutta {

using namespace dlpverify;
using namespace dlpverify::dlp;
namespace tt = boost::test_tools;

namespace {
// Every term of docs/model.md §1 on, C_D(Re) law: the step formulas must hold for the whole state.
Physics everything_on() {
  Physics physics;
  physics.terms.drag = true;
  physics.terms.drag_law = DragLaw::reynolds;
  physics.terms.gravity = true;
  physics.terms.heat = true;
  physics.terms.burning = true;
  return physics;
}

Physics drag_only() {
  Physics physics;
  physics.terms.drag = true;
  return physics;
}

// The outermost particle of docs/model.md §2 (ξ = 1, speed u_s = 100 m/s), turned off the lattice axes.
ParticleState moving_particle() {
  const Parameters p;
  return {1e-3, -2e-4, 5e-4, 60.0, -48.0, 64.0, p.t_particle, p.mass0()};  // ‖v‖ = 100 (by hand: 3600 + 2304 + 4096)
}

// dy/dt = −K ‖v‖ v with K = 1.6 m⁻¹ (docs/model.md §8), written out by hand for the velocity only.
using Velocity = std::array<double, 3>;
Velocity drag_acceleration(const Velocity& v) {
  const double K = 1.6;
  const double s = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {-K * s * v[0], -K * s * v[1], -K * s * v[2]};
}
Velocity plus(const Velocity& a, double h, const Velocity& b) { return {a[0] + h * b[0], a[1] + h * b[1], a[2] + h * b[2]}; }

Velocity velocity_of(const ParticleState& y) { return {y[VX], y[VY], y[VZ]}; }

void check_velocity(const ParticleState& y, const Velocity& expected, double tolerance) {
  for (int i = 0; i < 3; ++i) BOOST_TEST(y[VX + i] == expected[i], tt::tolerance(tolerance));
}

double norm3(const ParticleState& a, const ParticleState& b, int first) {
  double sum = 0.0;
  for (int i = first; i < first + 3; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

template <const auto& Tableau>
struct Method {
  static constexpr int order = Tableau.order;
  static void step(const Physics& physics, double t, double dt, ParticleState& y) {
    test::step_particle<Tableau>(physics, t, dt, y);
  }
  static std::string name() {
    if (&Tableau == static_cast<const void*>(&tableau::euler)) return "euler";
    if (&Tableau == static_cast<const void*>(&tableau::midpoint)) return "midpoint";
    if (&Tableau == static_cast<const void*>(&tableau::heun)) return "heun";
    return "rk4";
  }
};
using Methods = boost::mpl::list<Method<tableau::euler>, Method<tableau::midpoint>, Method<tableau::heun>,
                                 Method<tableau::rk4>>;
}  // namespace

BOOST_AUTO_TEST_SUITE(runge_kutta)

// docs/model.md §3 (seed eqs. 27–30): y½ = y + (Δt/2) f(y), y1 = y + Δt f(y½), for the whole state.
BOOST_AUTO_TEST_CASE(midpoint_step_by_hand) {
  const ParticleRates f(everything_on());
  const ParticleState y0 = moving_particle();
  const double dt = 1e-4;

  ParticleState k1, half, k2, expected;
  f(0.0, y0, k1);
  for (int i = 0; i < kFields; ++i) half[i] = y0[i] + (dt / 2.0) * k1[i];
  f(dt / 2.0, half, k2);
  for (int i = 0; i < kFields; ++i) expected[i] = y0[i] + dt * k2[i];

  ParticleState y = y0;
  test::step_particle<tableau::midpoint>(everything_on(), 0.0, dt, y);
  for (int i = 0; i < kFields; ++i) {
#ifdef __FMA__
    // With FMA instructions available (-march=native) the compiler may contract a·b + c
    // differently in the two computations: equal to a few ulp.
    BOOST_TEST(y[i] == expected[i], tt::tolerance(1e-15));
#else
    BOOST_TEST(y[i] == expected[i]);  // bitwise: the same operations in the same order
#endif
    BOOST_TEST(y[i] != y0[i], "field " << i << " did not change");  // every equation is active
  }
}

// docs/model.md §3 forward Euler on dv/dt = −K ‖v‖ v: v1 = v + Δt f(v).
BOOST_AUTO_TEST_CASE(euler_step_by_hand) {
  const ParticleState y0 = moving_particle();
  const double dt = 1e-3;
  const Velocity v = velocity_of(y0);
  const Velocity expected = plus(v, dt, drag_acceleration(v));
  ParticleState y = y0;
  test::step_particle<tableau::euler>(drag_only(), 0.0, dt, y);
  check_velocity(y, expected, 1e-14);
  for (int i = 0; i < 3; ++i) BOOST_TEST(y[X + i] == y0[X + i] + dt * y0[VX + i], tt::tolerance(1e-15));
}

// docs/model.md §3 Heun (explicit trapezoid): k1 = f(v), k2 = f(v + Δt k1), v1 = v + (Δt/2)(k1 + k2);
// the position gets x + (Δt/2)(v + (v + Δt k1)).
BOOST_AUTO_TEST_CASE(heun_step_by_hand) {
  const ParticleState y0 = moving_particle();
  const double dt = 1e-3;
  const Velocity v = velocity_of(y0);
  const Velocity k1 = drag_acceleration(v);
  const Velocity v_end = plus(v, dt, k1);
  const Velocity k2 = drag_acceleration(v_end);
  Velocity expected;
  for (int i = 0; i < 3; ++i) expected[i] = v[i] + dt / 2.0 * (k1[i] + k2[i]);
  ParticleState y = y0;
  test::step_particle<tableau::heun>(drag_only(), 0.0, dt, y);
  check_velocity(y, expected, 1e-14);
  for (int i = 0; i < 3; ++i)
    BOOST_TEST(y[X + i] == y0[X + i] + dt / 2.0 * (v[i] + v_end[i]), tt::tolerance(1e-14));
}

// docs/model.md §3 classical RK4: k1 = f(v), k2 = f(v + Δt/2 k1), k3 = f(v + Δt/2 k2), k4 = f(v + Δt k3),
// v1 = v + Δt/6 (k1 + 2 k2 + 2 k3 + k4); the position uses the stage velocities the same way.
BOOST_AUTO_TEST_CASE(rk4_step_by_hand) {
  const ParticleState y0 = moving_particle();
  const double dt = 1e-3;
  const Velocity v1 = velocity_of(y0);
  const Velocity k1 = drag_acceleration(v1);
  const Velocity v2 = plus(v1, dt / 2.0, k1);
  const Velocity k2 = drag_acceleration(v2);
  const Velocity v3 = plus(v1, dt / 2.0, k2);
  const Velocity k3 = drag_acceleration(v3);
  const Velocity v4 = plus(v1, dt, k3);
  const Velocity k4 = drag_acceleration(v4);
  Velocity expected, expected_x;
  for (int i = 0; i < 3; ++i) {
    expected[i] = v1[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    expected_x[i] = y0[X + i] + dt / 6.0 * (v1[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]);
  }
  ParticleState y = y0;
  test::step_particle<tableau::rk4>(drag_only(), 0.0, dt, y);
  check_velocity(y, expected, 1e-14);
  for (int i = 0; i < 3; ++i) BOOST_TEST(y[X + i] == expected_x[i], tt::tolerance(1e-14));
}

// The local (one-step) error of an order-p method is e(Δt) = C Δt^(p+1) (1 + D Δt + O(Δt²)), so the
// observed order q(Δt) = log2(e(Δt) / e(Δt/2)) − 1 = p + O(Δt), and the extrapolation
// 2 q(Δt/2) − q(Δt) = p + O(Δt²) cancels the first correction. Exact solution: docs/model.md §4.3.
// Steps Δt = 2e-4, 1e-4, 5e-5 s (K s0 Δt = 0.032 … 0.008): the raw q is within 0.05 of p, the
// extrapolated one within 0.001 (measured); the RK4 error (~1e-12 relative) stays far above round-off.
BOOST_AUTO_TEST_CASE_TEMPLATE(local_error_order_matches_tableau, M, Methods) {
  const Physics physics = drag_only();
  const ParticleState y0 = moving_particle();
  const double steps[3] = {2e-4, 1e-4, 5e-5};
  double error_position[3], error_velocity[3];
  for (int level = 0; level < 3; ++level) {
    ParticleState y = y0;
    M::step(physics, 0.0, steps[level], y);
    const ParticleState exact = exact::drag(physics, y0, steps[level]);
    error_position[level] = norm3(y, exact, X);
    error_velocity[level] = norm3(y, exact, VX);
  }
  for (const auto& [group, error] : {std::pair{"position", error_position}, std::pair{"velocity", error_velocity}}) {
    const double coarse = std::log2(error[0] / error[1]) - 1.0;
    const double fine = std::log2(error[1] / error[2]) - 1.0;
    const double extrapolated = 2.0 * fine - coarse;
    BOOST_TEST_MESSAGE(M::name() << " " << group << ": observed order " << coarse << ", " << fine << ", extrapolated "
                                 << extrapolated << " (tableau order " << M::order << ")");
    BOOST_TEST(std::abs(fine - M::order) <= 0.1, M::name() << " " << group << ": " << fine);
    BOOST_TEST(std::abs(extrapolated - M::order) <= 0.01, M::name() << " " << group << ": " << extrapolated);
  }
}

// The registry's integrators report their tableau's order (docs/model.md §3).
BOOST_AUTO_TEST_CASE(registry_orders) {
  BOOST_TEST(make_integrator("rk2")->order() == 2);
  BOOST_TEST(make_integrator("euler")->order() == 1);
  BOOST_TEST(make_integrator("heun")->order() == 2);
  BOOST_TEST(make_integrator("rk4")->order() == 4);
  BOOST_CHECK_THROW(make_integrator("rk3"), std::exception);
}

// ExplicitRungeKutta::advance on the R_out = 2 sphere (32 particles: r² = 1, 2, 3, 4 give 6 + 12 +
// 8 + 6) and on its first 13 and first 1 particles (advance works in blocks of 8: a partial block),
// every term on. The model is autonomous, so the start time must not matter; 0 steps must leave
// the cloud untouched; n steps must equal n single steps of every particle; and splitting the
// steps (4 then 6) must give the same cloud as 10 at once.
BOOST_AUTO_TEST_CASE(advance_on_a_tiny_cloud) {
  Lattice lattice;
  lattice.outer = 2;
  const Cloud sphere = make_cloud(lattice, Launch{}, Parameters{});
  BOOST_REQUIRE(sphere.size() == 32);
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  BOOST_TEST(rk2.order() == 2);
  BOOST_TEST(rk2.name() == "rk2");
  const double dt = 1e-5;
  const long steps = 10;

  // 32 particles: one block exactly; 13 and 1: a partial block.
  for (const Eigen::Index size : {Eigen::Index{32}, Eigen::Index{13}, Eigen::Index{1}}) {
    BOOST_TEST_CONTEXT(size << " particles") {
      const test::PhysicsProblem p(everything_on(), Cloud(State(sphere.state().topRows(size))));
      const State initial = p.problem->initial_state();

      State from_zero = initial;
      rk2.advance(*p, from_zero, 0.0, dt, steps);
      State from_later = initial;
      rk2.advance(*p, from_later, 123.456, dt, steps);
      BOOST_TEST((from_zero == from_later).all());
      BOOST_TEST((from_zero != initial).rowwise().any().all());  // every particle moved

      State untouched = initial;
      rk2.advance(*p, untouched, 0.0, dt, 0);
      BOOST_TEST((untouched == initial).all());

      // The block integrator against the per-particle hand-written midpoint rule.
      const ParticleRates f(everything_on());
      for (Eigen::Index m = 0; m < initial.rows(); ++m) {
        ParticleState y = Cloud(initial).particle(m);
        for (long n = 0; n < steps; ++n) {
          ParticleState k1, half, k2;
          f(n * dt, y, k1);
          for (int i = 0; i < kFields; ++i) half[i] = y[i] + (dt / 2.0) * k1[i];
          f(n * dt + dt / 2.0, half, k2);
          for (int i = 0; i < kFields; ++i) y[i] = y[i] + dt * k2[i];
        }
        const ParticleState advanced = Cloud(from_zero).particle(m);
#ifdef __FMA__
        for (int i = 0; i < kFields; ++i) BOOST_TEST_REQUIRE(advanced[i] == y[i], tt::tolerance(1e-14));
#else
        for (int i = 0; i < kFields; ++i) BOOST_TEST_REQUIRE(advanced[i] == y[i]);  // bitwise
#endif
      }

      State split = initial;
      rk2.advance(*p, split, 0.0, dt, 4);
      rk2.advance(*p, split, 4 * dt, dt, 6);
      BOOST_TEST((split == from_zero).all());
    }
  }

  const test::PhysicsProblem none(everything_on(), Cloud(0));
  State empty(0, kFields);
  rk2.advance(*none, empty, 0.0, dt, steps);
  BOOST_TEST(empty.rows() == 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_runge_kutta
