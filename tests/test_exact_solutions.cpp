// The closed forms of docs/model.md §4.1–4.3 against their ODE (exact::ode_residual), spot values of the
// closed forms, and the seed's wrong drag solution (docs/model.md §9), which the residual must reject.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "problems/dlp/exact/drag.hpp"
#include "problems/dlp/exact/gravity.hpp"
#include "dlp_support.hpp"
#include "problems/dlp/exact/time_scale.hpp"
#include "problems/dlp/exact/published.hpp"
#include "problems/dlp/exact/similarity.hpp"
#include "problems/dlp/cloud.hpp"

namespace unit_exact_solutions {

using namespace dlpverify;
using namespace dlpverify::dlp;
namespace tt = boost::test_tools;

namespace {
constexpr double kResidualTolerance = 1e-8;  // the brief's bound for a closed form that solves its ODE

Physics physics_with(bool drag, bool gravity) {
  Physics physics;
  physics.terms.drag = drag;
  physics.terms.gravity = gravity;
  return physics;
}

// The R_out = 10 sphere of docs/model.md §2 (4,168 particles), built once.
const Cloud& small_cloud() {
  static const Cloud cloud = [] {
    Lattice lattice;
    lattice.outer = 10;
    return make_cloud(lattice, Launch{}, Parameters{});
  }();
  return cloud;
}

// Particles to check: from the cloud (outermost (−10,0,0)Δ, an inner one, one on a diagonal), plus
// one at rest at the origin and one at rest off the origin (the sphere itself has no particle at
// the origin: 1 ≤ r).
std::vector<ParticleState> particles() {
  const Cloud& cloud = small_cloud();
  const Parameters p;
  std::vector<ParticleState> list{cloud.particle(0), cloud.particle(cloud.size() / 2), cloud.particle(cloud.size() / 3),
                                  cloud.particle(cloud.size() - 1)};
  list.push_back({0.0, 0.0, 0.0, 0.0, 0.0, 0.0, p.t_particle, p.mass0()});
  list.push_back({3e-4, -2e-4, 5e-4, 0.0, 0.0, 0.0, p.t_particle, p.mass0()});
  return list;
}

// τ from 0 through the launch (t0 = 1e-5 s at R_out = 10), the drag time 1/(K u_s) = 6.25 ms, and
// far past it (K s0 τ = 160 at 1 s).
const std::vector<double> kTaus{0.0, 1e-7, 1e-5, 1e-3, 6.25e-3, 5e-2, 1.0};

void check_residuals(exact::ParticleSolution solution, const Physics& physics) {
  double largest = 0.0;
  for (const ParticleState& y0 : particles())
    for (double tau : kTaus) {
      const test::ParticleResidual r = test::particle_residual(solution, physics, y0, tau);
      BOOST_TEST(r.max() <= kResidualTolerance, "tau = " << tau << ", particle at (" << y0[X] << ", " << y0[Y] << ", "
                                                         << y0[Z] << "): residual x " << r.position << ", v "
                                                         << r.velocity << ", T " << r.temperature << ", m " << r.mass);
      largest = std::max(largest, r.max());
    }
  // Over the whole R_out = 10 cloud at two times.
  for (double tau : {1e-4, 2e-2}) {
    const test::ParticleResidual r = test::cloud_residual(solution, physics, small_cloud(), tau);
    BOOST_TEST(r.max() <= kResidualTolerance, "whole cloud, tau = " << tau << ": " << r.max());
    largest = std::max(largest, r.max());
  }
  BOOST_TEST_MESSAGE("largest ODE residual: " << largest);
}

// docs/model.md §4.5 at rest (s0 = 0, Nu = 2): T = T_a + (T0 − T_a) exp(−τ/τ_h), τ_h = ρ_p d² c_s / (12 k_a).
ParticleState heat_at_rest(const Physics& physics, const ParticleState& y0, double tau) {
  const Parameters& p = physics.parameters;
  const double relaxation = p.rho_particle * p.diameter * p.diameter * p.cs_particle / (12.0 * p.k_gas());
  ParticleState y = y0;
  y[TEMPERATURE] = p.t_gas + (y0[TEMPERATURE] - p.t_gas) * std::exp(-tau / relaxation);
  return y;
}

// docs/model.md §4.6 at rest: d = d0 − β τ, β = 2 c_b / (π ρ_p), m = π ρ_p d³ / 6; with heat at Nu = 2,
// T = T_a + (T0 − T_a) exp(−Λ), Λ = (12 k_a / (ρ_p c_s β)) (1/d − 1/d0).
ParticleState burning_at_rest(const Physics& physics, const ParticleState& y0, double tau) {
  const Parameters& p = physics.parameters;
  const double pi = std::numbers::pi;
  const double beta = 2.0 * p.burn_rate / (pi * p.rho_particle);
  const double d0 = std::cbrt(6.0 * y0[MASS] / (pi * p.rho_particle));
  const double d = d0 - beta * tau;
  ParticleState y = y0;
  y[MASS] = pi * p.rho_particle * d * d * d / 6.0;
  if (physics.terms.heat) {
    const double exponent = 12.0 * p.k_gas() / (p.rho_particle * p.cs_particle * beta) * (1.0 / d - 1.0 / d0);
    y[TEMPERATURE] = p.t_gas + (y0[TEMPERATURE] - p.t_gas) * std::exp(-exponent);
  }
  return y;
}

// docs/model.md §4.3 with K off by one part in a million: the residual must see it (≈ 1e-6 on v).
ParticleState drag_with_k_off_by_1e6(const Physics& physics, const ParticleState& y0, double tau) {
  Physics wrong = physics;
  wrong.parameters.cd *= 1.0 + 1e-6;
  const ParticleState y = exact::drag(wrong, y0, tau);
  return y;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(exact_solutions)

BOOST_AUTO_TEST_CASE(similarity_solves_its_ode) { check_residuals(exact::similarity, physics_with(false, false)); }

BOOST_AUTO_TEST_CASE(gravity_solves_its_ode) { check_residuals(exact::gravity, physics_with(false, true)); }

BOOST_AUTO_TEST_CASE(drag_solves_its_ode) { check_residuals(exact::drag, physics_with(true, false)); }

// The time scales the residual's step is chosen from. docs/model.md §8: the outermost particle's drag time
// 1/(K u_s) = 1 / (1.6 · 100) = 6.25 ms. docs/model.md §4.5: at rest (Nu = 2) T relaxes with time constant
// ρ_p d² c_s / (12 k_a) = 2700 · 1e-8 · 900 / (12 · 0.025125) = 0.0243 / 0.3015 s.
BOOST_AUTO_TEST_CASE(time_scales) {
  const ParticleState outermost = small_cloud().particle(0);
  BOOST_TEST(exact::time_scale(physics_with(true, false), outermost) == 6.25e-3, tt::tolerance(1e-14));
  BOOST_TEST(std::isinf(exact::time_scale(physics_with(false, true), outermost)));  // gravity alone: none
  Physics heat;
  heat.terms.heat = true;
  ParticleState at_rest = outermost;
  at_rest[VX] = at_rest[VY] = at_rest[VZ] = 0.0;
  BOOST_TEST(exact::time_scale(heat, at_rest) == 0.0243 / 0.3015, tt::tolerance(1e-13));
  // Drag + gravity at rest: τ_c = v_t / g = 1 / √(g K) (docs/model.md §4.4).
  BOOST_TEST(exact::time_scale(physics_with(true, true), at_rest) == 1.0 / std::sqrt(9.81 * 1.6), tt::tolerance(1e-14));
}

// docs/model.md §4.3 at K s0 τ = 1: s = s0 / 2 and the particle has moved ln 2 / K along î.
BOOST_AUTO_TEST_CASE(drag_spot_values) {
  const Physics physics = physics_with(true, false);
  const double K = 1.6;  // docs/model.md §8
  for (const ParticleState& y0 : particles()) {
    const double s0 = std::sqrt(y0[VX] * y0[VX] + y0[VY] * y0[VY] + y0[VZ] * y0[VZ]);
    if (s0 == 0.0) {
      // At rest it stays where it is.
      const ParticleState y = exact::drag(physics, y0, 1.0);
      for (int f = 0; f < kFields; ++f) BOOST_TEST(y[f] == y0[f]);
      continue;
    }
    const double tau = 1.0 / (K * s0);
    const ParticleState y = exact::drag(physics, y0, tau);
    for (int i = 0; i < 3; ++i) {
      BOOST_TEST(y[VX + i] == y0[VX + i] / 2.0, tt::tolerance(1e-14));
      BOOST_TEST(y[X + i] == y0[X + i] + y0[VX + i] / s0 * std::log(2.0) / K, tt::tolerance(1e-13));
    }
  }
  // The outermost particle (s0 = u_s = 100 m/s along −î): s = 50 m/s at τ = 6.25 ms.
  const ParticleState y = exact::drag(physics, small_cloud().particle(0), 6.25e-3);
  BOOST_TEST(y[VX] == -50.0, tt::tolerance(1e-14));
}

// docs/model.md §4.2: relative to the vacuum path, z drops by g τ² / 2 and v_z by g τ; x, y unchanged.
BOOST_AUTO_TEST_CASE(gravity_spot_values) {
  const Physics physics = physics_with(false, true);
  const double g = 9.81;  // docs/model.md §8
  for (const ParticleState& y0 : particles())
    for (double tau : {1e-3, 0.1, 2.0}) {
      const ParticleState y = exact::gravity(physics, y0, tau);
      const ParticleState vacuum = exact::similarity(physics, y0, tau);
      BOOST_TEST(y[X] == vacuum[X]);
      BOOST_TEST(y[Y] == vacuum[Y]);
      BOOST_TEST(y[Z] - vacuum[Z] == -0.5 * g * tau * tau, tt::tolerance(1e-12));
      BOOST_TEST(y[VZ] - vacuum[VZ] == -g * tau, tt::tolerance(1e-12));
      BOOST_TEST(y[VX] == y0[VX]);
      BOOST_TEST(y[TEMPERATURE] == y0[TEMPERATURE]);
      BOOST_TEST(y[MASS] == y0[MASS]);
    }
}

// docs/model.md §4.1: x = x0 + v0 τ, i.e. x = ξ u_s t î for the lattice cloud (t = t0 + τ, t0 = 1e-5 s).
BOOST_AUTO_TEST_CASE(similarity_spot_values) {
  const ParticleState y0 = small_cloud().particle(0);  // ξ = 1, î = −x̂
  const ParticleState y = exact::similarity(physics_with(false, false), y0, 1e-3);
  BOOST_TEST(y[X] == -100.0 * (1e-5 + 1e-3), tt::tolerance(1e-14));
  BOOST_TEST(y[VX] == -100.0);
}

// docs/model.md §9: seed eq. 23 does not solve dv/dt = −K ‖v‖ v; its residual is of order one
// (by hand: |−K s0² − K³ s0²| / (K³ s0²) = (1 + K²) / K² ≈ 1.39 at any τ < 1/s0).
BOOST_AUTO_TEST_CASE(seed_eq23_is_not_a_solution) {
  const Physics physics = physics_with(true, false);
  for (const ParticleState& y0 : particles()) {
    if (y0[VX] == 0.0 && y0[VY] == 0.0 && y0[VZ] == 0.0) continue;  // eq. 23 divides by s0
    for (double tau : {0.0, 1e-5, 1e-3}) {
      const test::ParticleResidual r = test::particle_residual(&exact::seed_drag_eq23, physics, y0, tau);
      BOOST_TEST(r.velocity >= 1e-2, "tau = " << tau << ": " << r.velocity);
      BOOST_TEST(r.max() >= 1e-2);
      BOOST_TEST(r.velocity == (1.0 + 1.6 * 1.6) / (1.6 * 1.6), tt::tolerance(1e-6));
      BOOST_TEST(r.position <= kResidualTolerance);  // its position is consistent with its velocity
    }
  }
}

// The temperature and mass groups of the checker, on the at-rest closed forms of docs/model.md §4.5 and
// §4.6 (burn-out at τ_b = d0/β = π ρ_p d0 / (2 c_b) = 42.4 ms, docs/model.md §8: the last τ is 10 ms short).
BOOST_AUTO_TEST_CASE(heat_and_burning_at_rest_solve_their_odes) {
  const Parameters p;
  const ParticleState at_rest{3e-4, -2e-4, 5e-4, 0.0, 0.0, 0.0, p.t_particle, p.mass0()};
  Physics heat;
  heat.terms.heat = true;
  Physics burning;
  burning.terms.burning = true;
  Physics both = burning;
  both.terms.heat = true;
  double largest = 0.0;
  for (double tau : {0.0, 1e-4, 1e-2, 3e-2}) {
    const test::ParticleResidual h = test::particle_residual(heat_at_rest, heat, at_rest, tau);
    const test::ParticleResidual b = test::particle_residual(burning_at_rest, burning, at_rest, tau);
    const test::ParticleResidual hb = test::particle_residual(burning_at_rest, both, at_rest, tau);
    BOOST_TEST(h.max() <= kResidualTolerance, "heat, tau = " << tau << ": " << h.temperature);
    BOOST_TEST(b.max() <= kResidualTolerance, "burning, tau = " << tau << ": " << b.mass);
    BOOST_TEST(hb.max() <= kResidualTolerance, "heat + burning, tau = " << tau << ": " << hb.temperature << ", "
                                                                         << hb.mass);
    // The heat solution with burning on misses dm/dt = −c_b d² entirely: residual 1 on m.
    BOOST_TEST(test::particle_residual(heat_at_rest, both, at_rest, tau).mass == 1.0, tt::tolerance(1e-9));
    largest = std::max({largest, h.max(), b.max(), hb.max()});
  }
  BOOST_TEST_MESSAGE("largest ODE residual (heat, burning at rest): " << largest);
}

// The residual resolves a part-per-million error in K (dv/dt = −K′ s² vs −K s²: 1e-6 relative).
BOOST_AUTO_TEST_CASE(residual_resolves_a_1e6_error) {
  const Physics physics = physics_with(true, false);
  const ParticleState y0 = small_cloud().particle(0);
  for (double tau : {0.0, 1e-3, 5e-2}) {
    const test::ParticleResidual r = test::particle_residual(drag_with_k_off_by_1e6, physics, y0, tau);
    BOOST_TEST(r.velocity == 1e-6, tt::tolerance(1e-3));
  }
}

// A NaN from a closed form makes the residual NaN, never a pass.
BOOST_AUTO_TEST_CASE(nan_propagates) {
  test::ParticleResidual r;
  r.mass = std::nan("");
  BOOST_TEST(std::isnan(r.max()));
  BOOST_TEST(!(r.max() <= kResidualTolerance));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_exact_solutions
