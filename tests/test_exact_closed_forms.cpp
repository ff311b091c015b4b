// The closed forms of docs/model.md §4.4–4.6 and the seed's published forms (docs/model.md §9):
//   - each closed form satisfies its ODE (exact::ode_residual ≤ 1e-8 relative) at several τ and
//     particles, every branch of §4.4 included;
//   - each agrees with CVODE (Adams, rtol 1e-12, per-field atol) on a small cloud to ≤ 1e-9
//     relative L2 per active variable;
//   - spot values from docs/model.md §4/§8 and limits (c_b → 0, a very slow particle);
//   - the seed's eqs. 23 and 26 fail the residual by orders of magnitude.
// Every number asserted comes from docs/model.md or from a closed form written out here.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "dlpverify/norms.hpp"
#include "problems/dlp/exact/burn.hpp"
#include "problems/dlp/exact/cloud_solution.hpp"
#include "problems/dlp/exact/drag.hpp"
#include "problems/dlp/exact/drag_heat.hpp"
#include "dlp_support.hpp"
#include "problems/dlp/exact/time_scale.hpp"
#include "problems/dlp/exact/published.hpp"
#include "problems/dlp/exact/vertical_drag_gravity.hpp"
#include "integrators/sundials/cvode_integrator.hpp"
#include "dlpverify/errors.hpp"
#include "problems/dlp/cloud.hpp"
#include "problems/dlp/rates.hpp"

namespace unit_exact_closed_forms {

using namespace dlpverify;
using namespace dlpverify::dlp;
namespace tt = boost::test_tools;

namespace {
constexpr double kResidualTolerance = 1e-8;  // the brief's bound for a closed form that solves its ODE
constexpr double kCvodeTolerance = 1e-9;     // relative L2 distance to CVODE at rtol 1e-12
constexpr double kPi = std::numbers::pi;

Physics physics_with(Terms terms) {
  Physics physics;
  physics.terms = terms;
  return physics;
}
const Terms kVertical{.drag = true, .gravity = true};
const Terms kDragHeat{.drag = true, .heat = true};
const Terms kBurn{.drag = true, .burning = true};
const Terms kBurnHeat{.drag = true, .heat = true, .burning = true};

ParticleState particle(double x, double y, double z, double vx, double vy, double vz) {
  const Parameters p;
  return {x, y, z, vx, vy, vz, p.t_particle, p.mass0()};
}

// The R_out = 4 lattice sphere (docs/model.md §2; t0 = 4 µs) plus one particle at rest off the origin.
Cloud small_cloud_with_rest() {
  Lattice lattice;
  lattice.outer = 4;
  const Cloud lattice_cloud = make_cloud(lattice, Launch{}, Parameters{});
  Cloud cloud(lattice_cloud.size() + 1);
  for (Eigen::Index p = 0; p < lattice_cloud.size(); ++p) cloud.set_particle(p, lattice_cloud.particle(p));
  cloud.set_particle(lattice_cloud.size(), particle(3e-4, -2e-4, 5e-4, 0.0, 0.0, 0.0));
  return cloud;
}

// Moving particles of the lattice (outermost, a middle one, a slow inner one) and one at rest.
std::vector<ParticleState> sample_particles() {
  const Cloud cloud = small_cloud_with_rest();
  std::vector<ParticleState> list{cloud.particle(0), cloud.particle(cloud.size() / 2), cloud.particle(cloud.size() / 3),
                                  cloud.particle(cloud.size() - 1)};
  Lattice lattice;
  lattice.outer = 10;
  const Cloud seed = make_cloud(lattice, Launch{}, Parameters{});
  list.push_back(seed.particle(0));  // 100 m/s
  // The slowest particle of the R_out = 10 sphere: ξ = 1/10, 10 m/s.
  for (Eigen::Index p = 0; p < seed.size(); ++p) {
    const ParticleState y = seed.particle(p);
    if (std::abs(y[X] - 1e-4) < 1e-12 && y[Y] == 0.0 && y[Z] == 0.0) list.push_back(y);
  }
  return list;
}

std::string describe(const ParticleState& y0) {
  std::ostringstream text;
  text << "particle at (" << y0[X] << ", " << y0[Y] << ", " << y0[Z] << ") with v0 = (" << y0[VX] << ", " << y0[VY]
       << ", " << y0[VZ] << ")";
  return text.str();
}

// Checks the residual at τ and returns it.
double checked_residual(exact::ParticleSolution solution, const Physics& physics, const ParticleState& y0, double tau) {
  const test::ParticleResidual r = test::particle_residual(solution, physics, y0, tau);
  BOOST_TEST(r.max() <= kResidualTolerance, "tau = " << tau << ", " << describe(y0) << ": residual x " << r.position
                                                     << ", v " << r.velocity << ", T " << r.temperature << ", m "
                                                     << r.mass);
  return r.max();
}

// CVODE (Adams, rtol 1e-12, atol per field = 1e-12 × the field's size) from τ = 0 to τ, against the
// closed form: the relative L2 distance of each group the terms make active (docs/model.md §5).
// restarts: times in (0, τ) where the right-hand side is not smooth (the apexes of docs/model.md §4.4, where
// −K |w| w is only C¹); CVODE is stopped and restarted there, as at any known non-smoothness, so
// its multistep history does not straddle it.
std::vector<std::pair<std::string, double>> cvode_distances(exact::ParticleSolution solution, const Physics& physics,
                                                           const Cloud& initial, double tau,
                                                           std::vector<double> restarts = {}) {
  const test::PhysicsProblem problem(physics, initial);
  CvodeSettings settings;
  settings.rtol = 1e-12;
  settings.method = CvodeMethod::adams;
  settings.atol = absolute_tolerances(*problem, initial.state(), settings.rtol);
  CvodeIntegrator cvode(settings);
  State numerical = initial.state();
  std::sort(restarts.begin(), restarts.end());
  restarts.push_back(tau);
  double t = 0.0;
  long steps = 0;
  for (double stop : restarts) {
    if (!(stop > t && stop <= tau)) continue;
    cvode.advance(*problem, numerical, t, stop - t, 1);
    steps += cvode.statistics().steps.value();
    t = stop;
  }
  const Cloud exact = exact::evaluate(solution, physics, initial, tau);
  std::vector<std::pair<std::string, double>> distances;
  for (const Variable& group : problem.problem->variables()) {
    const double distance = error_norms(numerical, exact.state(), group).relative;
    BOOST_TEST(distance <= kCvodeTolerance, group.name << ": CVODE vs closed form " << distance);
    BOOST_TEST_MESSAGE("  CVODE vs closed form, " << group.name << ": " << distance);
    distances.emplace_back(group.name, distance);
  }
  BOOST_TEST_MESSAGE("  CVODE steps: " << steps << " in " << restarts.size() << " leg(s)");
  return distances;
}

// ---------------------------------------------------------------------------------------------
// docs/model.md §4.4 — a vertical cloud that takes every branch by τ = 0.3 s.
// v_t = √(9.81/1.6) = 2.476 m/s, τ_c = 0.2525 s; a rising particle stops at τ_a = τ_c atan(w0/v_t)
// < τ_c π/2 = 0.397 s: 1 and 2 m/s cross the apex before 0.3 s (τ_a = 0.098, 0.163 s), 10 and 100 m/s
// do not (0.336, 0.390 s).
const Parameters kDefaults;
const double kTerminal = std::sqrt(9.81 / 1.6);

std::vector<ParticleState> vertical_particles() {
  std::vector<ParticleState> list;
  // On the z axis of the R_out = 10 lattice, launched with the similarity velocity ±ξ u_s (docs/model.md §2).
  for (int k : {-10, -3, 1, 5, 10}) list.push_back(particle(0.0, 0.0, k * 1e-4, 0.0, 0.0, k * 10.0));
  for (double w0 : {1.0, 2.0, 0.0, -1.0, -2.4, -kTerminal, -2.6, -100.0, -1e4})
    list.push_back(particle(0.0, 0.0, 5e-4, 0.0, 0.0, w0));
  return list;
}

Cloud cloud_of(const std::vector<ParticleState>& particles) {
  Cloud cloud(static_cast<Eigen::Index>(particles.size()));
  for (std::size_t p = 0; p < particles.size(); ++p) cloud.set_particle(static_cast<Eigen::Index>(p), particles[p]);
  return cloud;
}

// docs/model.md §4.4 exactly as printed (atan, atanh, coth, ln of ratios), for well-conditioned inputs.
ParticleState spec_vertical(const ParticleState& y0, double tau) {
  const double K = 1.6, vt = kTerminal, tc = vt / 9.81, w0 = y0[VZ];
  ParticleState y = y0;
  if (w0 > 0.0) {
    const double phi0 = std::atan(w0 / vt);
    if (tau <= tc * phi0) {
      y[VZ] = vt * std::tan(phi0 - tau / tc);
      y[Z] = y0[Z] + std::log(std::cos(phi0 - tau / tc) / std::cos(phi0)) / K;
      return y;
    }
    const double za = y0[Z] + std::log(1.0 / std::cos(phi0)) / K, sigma = tau / tc - phi0;
    y[VZ] = -vt * std::tanh(sigma);
    y[Z] = za - std::log(std::cosh(sigma)) / K;
  } else if (-w0 < vt) {
    const double psi0 = std::atanh(-w0 / vt);
    y[VZ] = -vt * std::tanh(psi0 + tau / tc);
    y[Z] = y0[Z] - std::log(std::cosh(psi0 + tau / tc) / std::cosh(psi0)) / K;
  } else {
    const double psi0 = std::atanh(vt / -w0);
    y[VZ] = -vt / std::tanh(psi0 + tau / tc);
    y[Z] = y0[Z] - std::log(std::sinh(psi0 + tau / tc) / std::sinh(psi0)) / K;
  }
  return y;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(closed_forms)

// ---- docs/model.md §4.4 vertical drag + gravity ----------------------------------------------------------

// docs/model.md §8: K = 3 · 1.2 · 0.48 / (4 · 2700 · 1e-4) = 1.6 m⁻¹; v_t = √(g/K); docs/model.md §4.4: K v_t τ_c = 1.
BOOST_AUTO_TEST_CASE(vertical_scales) {
  BOOST_TEST(kDefaults.drag_constant() == 1.6, tt::tolerance(1e-14));
  BOOST_TEST(exact::terminal_speed(kDefaults) == std::sqrt(9.81 / 1.6), tt::tolerance(1e-14));
  BOOST_TEST(exact::drag_gravity_time(kDefaults) == std::sqrt(9.81 / 1.6) / 9.81, tt::tolerance(1e-14));
  BOOST_TEST(kDefaults.drag_constant() * exact::terminal_speed(kDefaults) * exact::drag_gravity_time(kDefaults) == 1.0,
             tt::tolerance(1e-15));
  // At v_t drag balances gravity: the rates vanish.
  ParticleState rate;
  ParticleRates(physics_with(kVertical))(0.0, particle(0, 0, 0, 0, 0, -exact::terminal_speed(kDefaults)), rate);
  BOOST_TEST(std::abs(rate[VZ]) <= 1e-14 * 9.81);
}

BOOST_AUTO_TEST_CASE(vertical_branch_classifier) {
  const Physics physics = physics_with(kVertical);
  using B = exact::VerticalBranch;
  const double vt = exact::terminal_speed(kDefaults);
  const auto branch = [&](double w0, double tau) { return exact::vertical_branch(physics, particle(0, 0, 0, 0, 0, w0), tau); };
  BOOST_TEST((branch(10.0, 0.3) == B::rising));
  BOOST_TEST((branch(1.0, 0.3) == B::rising_through_apex));
  BOOST_TEST((branch(0.0, 0.3) == B::falling_slower));
  BOOST_TEST((branch(-1.0, 0.3) == B::falling_slower));
  BOOST_TEST((branch(-vt, 0.3) == B::terminal));
  BOOST_TEST((branch(-100.0, 0.3) == B::falling_faster));
  // The apex time τ_a = τ_c atan(w0/v_t) separates the two rising branches.
  const double apex = exact::apex_time(physics, particle(0, 0, 0, 0, 0, 1.0));
  BOOST_TEST(apex == exact::drag_gravity_time(kDefaults) * std::atan(1.0 / vt), tt::tolerance(1e-14));
  BOOST_TEST((branch(1.0, apex) == B::rising));
  BOOST_TEST((branch(1.0, std::nextafter(apex, 1.0)) == B::rising_through_apex));
  BOOST_TEST(exact::to_string(B::rising_through_apex) == "rising-through-apex");
  // The test cloud below takes every branch by τ = 0.3 s.
  std::array<int, exact::kVerticalBranches> counts{};
  for (const ParticleState& y0 : vertical_particles()) ++counts[static_cast<int>(exact::vertical_branch(physics, y0, 0.3))];
  for (int b = 0; b < exact::kVerticalBranches; ++b)
    BOOST_TEST(counts[b] > 0, exact::to_string(static_cast<B>(b)) << ": " << counts[b] << " particles");
}

BOOST_AUTO_TEST_CASE(vertical_matches_spec_formulas) {
  // The stable forms (addition theorems) against docs/model.md §4.4 as printed, where the printed form is
  // well-conditioned (away from v_t and with moderate arguments).
  const Physics physics = physics_with(kVertical);
  for (double w0 : {1.0, 10.0, 0.0, -1.0, -2.0, -3.0, -20.0})
    for (double tau : {1e-3, 0.05, 0.2, 0.6, 2.0}) {
      const ParticleState y0 = particle(1e-4, -2e-4, 5e-4, 0.0, 0.0, w0);
      const ParticleState ours = exact::vertical_drag_gravity(physics, y0, tau), spec = spec_vertical(y0, tau);
      BOOST_TEST(ours[VZ] == spec[VZ], tt::tolerance(1e-12) << "w0 = " << w0 << ", tau = " << tau);
      BOOST_TEST(ours[Z] == spec[Z], tt::tolerance(1e-12) << "w0 = " << w0 << ", tau = " << tau);
      BOOST_TEST(ours[X] == y0[X]);
      BOOST_TEST(ours[Y] == y0[Y]);
      BOOST_TEST(ours[VX] == 0.0);
      BOOST_TEST(ours[TEMPERATURE] == y0[TEMPERATURE]);
      BOOST_TEST(ours[MASS] == y0[MASS]);
    }
  // Terminal: w = −v_t, z = z0 − v_t τ.
  const ParticleState terminal = particle(0, 0, 0, 0, 0, -kTerminal);
  for (double tau : {1e-3, 1.0, 1e3}) {
    const ParticleState y = exact::vertical_drag_gravity(physics, terminal, tau);
    BOOST_TEST(y[VZ] == -kTerminal, tt::tolerance(1e-15));
    BOOST_TEST(y[Z] == -kTerminal * tau, tt::tolerance(1e-14));
  }
  // Far past the apex every particle falls at v_t, and z stays finite (ln sinh/cosh of large σ).
  for (double w0 : {100.0, 0.0, -100.0}) {
    const ParticleState y = exact::vertical_drag_gravity(physics, particle(0, 0, 0, 0, 0, w0), 1e3);
    BOOST_TEST(y[VZ] == -kTerminal, tt::tolerance(1e-15));
    BOOST_TEST(std::isfinite(y[Z]));
  }
}

BOOST_AUTO_TEST_CASE(falling_faster_approaches_terminal_speed_from_above) {
  const Physics physics = physics_with(kVertical);
  const double vt = exact::terminal_speed(kDefaults), tc = exact::drag_gravity_time(kDefaults);
  for (double w0 : {-2.6, -100.0, -1e4}) {
    double previous = -w0;
    for (double tau : {1e-4, 1e-3, 1e-2, 0.1, 0.5, 1.0, 2.0, 3.0}) {
      const double speed = -exact::vertical_drag_gravity(physics, particle(0, 0, 0, 0, 0, w0), tau)[VZ];
      BOOST_TEST(speed > vt, "w0 = " << w0 << ", tau = " << tau << ": " << speed);
      BOOST_TEST(speed < previous, "w0 = " << w0 << ", tau = " << tau);
      previous = speed;
    }
    // Ten time scales on: (c − 1)(1 − tanh σ)/(1 + c tanh σ) < 2 e^(−20) ≈ 4e-9 of v_t.
    const double late = -exact::vertical_drag_gravity(physics, particle(0, 0, 0, 0, 0, w0), 10.0 * tc)[VZ];
    BOOST_TEST(late - vt < 4.2e-9 * vt);
    BOOST_TEST(late >= vt);
  }
}

BOOST_AUTO_TEST_CASE(vertical_needs_vertical_motion) {
  const Physics physics = physics_with(kVertical);
  const ParticleState oblique = particle(0, 0, 0, 1.0, 0.0, 5.0);
  BOOST_TEST(!exact::vertical_motion(oblique));
  BOOST_TEST(exact::vertical_motion(particle(1e-4, 2e-4, 0, 0, 0, 5.0)));
  const ParticleState y = exact::vertical_drag_gravity(physics, oblique, 0.1);
  for (int f = X; f <= VZ; ++f) BOOST_TEST(std::isnan(y[f]));
}

BOOST_AUTO_TEST_CASE(vertical_solves_its_ode) {
  const Physics physics = physics_with(kVertical);
  double largest = 0.0;
  int after_apex = 0;
  for (const ParticleState& y0 : vertical_particles()) {
    const double apex = exact::apex_time(physics, y0);
    std::vector<double> taus{0.0, 1e-4, 1e-2, 0.1, 0.3, 1.0, 3.0};
    if (y0[VZ] > 0.0) taus.insert(taus.end(), {0.5 * apex, apex + 0.1, apex + 2.0});
    for (double tau : taus) {
      if (y0[VZ] > 0.0 && std::abs(tau - apex) < 0.05) continue;  // the stencil (≤ ±0.01 s) must not straddle the apex
      if (y0[VZ] == 0.0 && tau == 0.0) continue;  // at rest at τ = 0 the particle is at its apex
      largest = std::max(largest, checked_residual(exact::vertical_drag_gravity, physics, y0, tau));
      if (y0[VZ] > 0.0 && tau > apex) ++after_apex;
    }
  }
  BOOST_TEST(after_apex >= 10);
  BOOST_TEST_MESSAGE("vertical drag + gravity, largest ODE residual: " << largest);
}

BOOST_AUTO_TEST_CASE(vertical_agrees_with_cvode) {
  BOOST_TEST_MESSAGE("vertical drag + gravity, tau = 0.3 s:");
  const Physics physics = physics_with(kVertical);
  std::vector<double> apexes;
  for (const ParticleState& y0 : vertical_particles())
    if (y0[VZ] > 0.0) apexes.push_back(exact::apex_time(physics, y0));
  cvode_distances(exact::vertical_drag_gravity, physics, cloud_of(vertical_particles()), 0.3, apexes);
}

// ---- docs/model.md §4.5 drag + heat ------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(drag_heat_spot_values) {
  const Physics physics = physics_with(kDragHeat);
  const Parameters& p = physics.parameters;
  // At rest: T relaxes with time constant ρ_p d² c_s / (12 k_a) = 0.0243 / 0.3015 s (docs/model.md §4.5).
  const ParticleState at_rest = particle(1e-4, 0, 0, 0, 0, 0);
  for (double tau : {1e-3, 0.05, 0.5}) {
    const ParticleState y = exact::drag_heat(physics, at_rest, tau);
    BOOST_TEST(y[TEMPERATURE] == 300.0 + 1200.0 * std::exp(-tau * 0.3015 / 0.0243), tt::tolerance(1e-13));
    BOOST_TEST(y[X] == at_rest[X]);
  }
  // Moving: x and v are docs/model.md §4.3's, m is unchanged, and I(τ) = 2(√(s0(1 + K s0 τ)) − √s0)/(K s0)
  // (the form that cancels, fine here) gives the same Λ.
  const ParticleState moving = particle(-1e-3, 0, 0, -100.0, 0, 0);
  for (double tau : {1e-3, 0.05}) {
    const ParticleState y = exact::drag_heat(physics, moving, tau), drag = exact::drag(physics, moving, tau);
    for (int f = X; f <= VZ; ++f) BOOST_TEST(y[f] == drag[f]);
    BOOST_TEST(y[MASS] == moving[MASS]);
    const double K = 1.6, s0 = 100.0, d = p.diameter;
    const double I = 2.0 * (std::sqrt(s0 * (1.0 + K * s0 * tau)) - std::sqrt(s0)) / (K * s0);
    const double Lambda = 6.0 * p.k_gas() / (p.rho_particle * d * d * p.cs_particle) *
                          (2.0 * tau + 0.6 * std::cbrt(0.72) * std::sqrt(1.2 * d / 1.8e-5) * I);
    BOOST_TEST(exact::drag_heat_exponent(physics, moving, tau) == Lambda, tt::tolerance(1e-12));
    BOOST_TEST(y[TEMPERATURE] == 300.0 + 1200.0 * std::exp(-Lambda), tt::tolerance(1e-12));
  }
  // Heat off: T stays T0.
  const ParticleState cold = exact::drag_heat(physics_with(Terms{.drag = true}), moving, 0.05);
  BOOST_TEST(cold[TEMPERATURE] == moving[TEMPERATURE]);
}

BOOST_AUTO_TEST_CASE(drag_heat_solves_its_ode) {
  const Physics physics = physics_with(kDragHeat);
  double moving = 0.0, resting = 0.0;
  for (const ParticleState& y0 : sample_particles()) {
    const bool at_rest = y0[VX] == 0.0 && y0[VY] == 0.0 && y0[VZ] == 0.0;
    for (double tau : {0.0, 1e-5, 1e-3, 1e-2, 5e-2, 0.5}) {
      const double r = checked_residual(exact::drag_heat, physics, y0, tau);
      (at_rest ? resting : moving) = std::max(at_rest ? resting : moving, r);
    }
  }
  const test::ParticleResidual cloud = test::cloud_residual(exact::drag_heat, physics, small_cloud_with_rest(), 0.02);
  BOOST_TEST(cloud.max() <= kResidualTolerance);
  BOOST_TEST_MESSAGE("drag + heat, largest ODE residual: moving " << std::max(moving, cloud.max()) << ", at rest "
                                                                  << resting);
}

BOOST_AUTO_TEST_CASE(drag_heat_agrees_with_cvode) {
  BOOST_TEST_MESSAGE("drag + heat, tau = 0.05 s:");
  cvode_distances(exact::drag_heat, physics_with(kDragHeat), small_cloud_with_rest(), 0.05);
}

// ---- docs/model.md §4.6 burning + drag (+ heat) -----------------------------------------------------------

// docs/model.md §8: τ_b = d0/β = π ρ_p d0 / (2 c_b) = π · 2700 · 1e-4 / 20 ≈ 42 ms (42.4 ms to 3 digits).
BOOST_AUTO_TEST_CASE(burn_out_time_with_defaults) {
  const double tau_b = exact::burn_out_time(kDefaults);
  BOOST_TEST(std::abs(tau_b - 0.0424) < 5e-5, "tau_b = " << tau_b);
  BOOST_TEST(tau_b == kPi * 2700.0 * 1e-4 / 20.0, tt::tolerance(1e-14));
  BOOST_TEST(exact::burn_diameter_rate(kDefaults) == 20.0 / (kPi * 2700.0), tt::tolerance(1e-14));
  Parameters no_burning;
  no_burning.burn_rate = 0.0;
  BOOST_TEST(std::isinf(exact::burn_out_time(no_burning)));
}

BOOST_AUTO_TEST_CASE(burn_past_burn_out_is_an_input_error) {
  const Physics physics = physics_with(kBurnHeat);
  const ParticleState y0 = particle(-1e-3, 0, 0, -100.0, 0, 0);
  const auto names_burn_out = [](const InputError& e) {
    const std::string message = e.what();
    BOOST_TEST_MESSAGE("InputError: " << message);
    // The library names the quantity (the command maps "duration" to --t-end).
    return message.find("duration = ") == 0 && message.find("tau_b = 0.0424115 s") != std::string::npos;
  };
  for (double tau : {0.0425, 0.05, 1.0}) {
    BOOST_CHECK_EXCEPTION(exact::burn(physics, y0, tau), InputError, names_burn_out);
    BOOST_CHECK_EXCEPTION(exact::check_before_burn_out(kDefaults, tau), InputError, names_burn_out);
  }
  BOOST_CHECK_NO_THROW(exact::check_before_burn_out(kDefaults, 0.0424));
  BOOST_CHECK_NO_THROW(exact::burn(physics, y0, 0.0424));
}

BOOST_AUTO_TEST_CASE(burn_spot_values) {
  const Physics physics = physics_with(kBurn);
  const double beta = 20.0 / (kPi * 2700.0), kappa = 3.0 * 1.2 * 0.48 / (4.0 * 2700.0);
  for (const ParticleState& y0 : sample_particles())
    for (double tau : {1e-4, 1e-2, 3e-2, 0.042}) {
      const ParticleState y = exact::burn(physics, y0, tau);
      // m = π ρ_p d³/6 with d = d0 − β τ.
      const double d = 1e-4 - beta * tau;
      BOOST_TEST(y[MASS] == kPi * 2700.0 * d * d * d / 6.0, tt::tolerance(1e-12));
      BOOST_TEST(y[TEMPERATURE] == y0[TEMPERATURE]);  // heat off
      const double s0 = std::sqrt(y0[VX] * y0[VX] + y0[VY] * y0[VY] + y0[VZ] * y0[VZ]);
      if (s0 == 0.0) {
        for (int f = X; f <= VZ; ++f) BOOST_TEST(y[f] == y0[f]);
        continue;
      }
      // s = 1 / (1/s0 + (κ/β) ln(d0/d)), along v0.
      const double s = 1.0 / (1.0 / s0 + kappa / beta * std::log(1e-4 / d));
      for (int i = 0; i < 3; ++i) BOOST_TEST(y[VX + i] == y0[VX + i] / s0 * s, tt::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(burn_tends_to_drag_as_burning_stops) {
  // c_b = 1e-9: β τ / d0 ~ 1e-11, so s and x match docs/model.md §4.3 to far better than 1e-6.
  Physics physics = physics_with(kBurnHeat);
  physics.parameters.burn_rate = 1e-9;
  Physics drag_heat = physics_with(kDragHeat);
  double worst_speed = 0.0, worst_position = 0.0, worst_exponent = 0.0;
  for (const ParticleState& y0 : sample_particles())
    for (double tau : {1e-3, 1e-2, 0.1}) {
      const ParticleState burning = exact::burn(physics, y0, tau), drag = exact::drag(physics, y0, tau);
      for (int i = 0; i < 3; ++i) {
        BOOST_TEST(burning[VX + i] == drag[VX + i], tt::tolerance(1e-6));
        BOOST_TEST(burning[X + i] == drag[X + i], tt::tolerance(1e-6));
        if (drag[VX + i] != 0.0)
          worst_speed = std::max(worst_speed, std::abs(burning[VX + i] / drag[VX + i] - 1.0));
        if (drag[X + i] != 0.0) worst_position = std::max(worst_position, std::abs(burning[X + i] / drag[X + i] - 1.0));
      }
      // The QAG path of Λ against docs/model.md §4.5's closed form: the same integral up to β τ / d0.
      const exact::HeatExponent h = exact::burn_heat_exponent(physics, y0, tau);
      const double closed = exact::drag_heat_exponent(drag_heat, y0, tau);
      BOOST_TEST(h.value == closed, tt::tolerance(1e-9));
      worst_exponent = std::max(worst_exponent, std::abs(h.value / closed - 1.0));
    }
  BOOST_TEST_MESSAGE("c_b = 1e-9 vs docs/model.md §4.3/4.5: speed " << worst_speed << ", position " << worst_position
                                                           << ", Lambda (QAG vs closed form) " << worst_exponent);
  // c_b = 0 exactly falls back to docs/model.md §4.3 / §4.5.
  physics.parameters.burn_rate = 0.0;
  const ParticleState y0 = sample_particles().front();
  const ParticleState y = exact::burn(physics, y0, 0.1), expected = exact::drag_heat(drag_heat, y0, 0.1);
  for (int f = 0; f < kFields; ++f) BOOST_TEST(y[f] == expected[f], tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(burn_heat_quadrature) {
  const Physics physics = physics_with(kBurnHeat);
  const Parameters& p = physics.parameters;
  const double beta = exact::burn_diameter_rate(p);
  // A particle at 1e-30 m/s: Re ~ 1e-29, so Nu − 2 ~ 1e-15 and QAG must reproduce the Nu = 2
  // closed form Λ = (12 k_a/(ρ_p c_s β))(1/d − 1/d0) — to its 1e-13 tolerance.
  const ParticleState crawling = particle(0, 0, 1e-4, 0, 0, 1e-30), at_rest = particle(0, 0, 1e-4, 0, 0, 0);
  for (double tau : {1e-5, 1e-3, 1e-2, 3e-2, 0.042}) {
    const double d = 1e-4 - beta * tau;
    const double closed = 12.0 * p.k_gas() / (p.rho_particle * p.cs_particle * beta) * (1.0 / d - 1.0 / 1e-4);
    const exact::HeatExponent slow = exact::burn_heat_exponent(physics, crawling, tau);
    const exact::HeatExponent rest = exact::burn_heat_exponent(physics, at_rest, tau);
    BOOST_TEST(slow.intervals > 0U);  // the QAG path
    BOOST_TEST(rest.intervals == 0U);  // the closed form
    BOOST_TEST(slow.value == closed, tt::tolerance(1e-12) << "tau = " << tau);
    BOOST_TEST(rest.value == closed, tt::tolerance(1e-11) << "tau = " << tau);  // (1/d − 1/d0) cancels here
    BOOST_TEST_MESSAGE("tau = " << tau << ": QAG (1e-30 m/s) vs closed form " << std::abs(slow.value / closed - 1.0)
                                << ", status " << slow.status << ", est. error " << slow.error / slow.value);
  }
  // The accuracy QAG reports over the sample particles and times (moving particles, Nu(Re)).
  double worst_estimate = 0.0;
  int failures = 0;
  std::size_t most_intervals = 0;
  for (const ParticleState& y0 : sample_particles())
    for (double tau : {-1e-5, 1e-5, 1e-3, 1e-2, 3e-2, 0.04, 0.0424}) {
      const exact::HeatExponent h = exact::burn_heat_exponent(physics, y0, tau);
      BOOST_TEST(std::isfinite(h.value));
      if (h.status != 0) ++failures;
      if (h.value != 0.0) worst_estimate = std::max(worst_estimate, h.error / std::abs(h.value));
      most_intervals = std::max(most_intervals, h.intervals);
    }
  BOOST_TEST(worst_estimate <= exact::kHeatQuadratureTolerance);
  BOOST_TEST_MESSAGE("QAG: worst estimated relative error " << worst_estimate << ", " << failures
                                                            << " non-success statuses, at most " << most_intervals
                                                            << " subintervals");
}

BOOST_AUTO_TEST_CASE(burn_solves_its_ode) {
  for (const Terms& terms : {kBurn, kBurnHeat}) {
    const Physics physics = physics_with(terms);
    double moving = 0.0, resting = 0.0;
    for (const ParticleState& y0 : sample_particles()) {
      const bool at_rest = y0[VX] == 0.0 && y0[VY] == 0.0 && y0[VZ] == 0.0;
      for (double tau : {0.0, 1e-5, 1e-3, 1e-2, 3e-2, 0.04}) {  // τ_b = 42.4 ms: the stencil stays before it
        const double r = checked_residual(exact::burn, physics, y0, tau);
        (at_rest ? resting : moving) = std::max(at_rest ? resting : moving, r);
      }
    }
    const test::ParticleResidual cloud = test::cloud_residual(exact::burn, physics, small_cloud_with_rest(), 0.02);
    BOOST_TEST(cloud.max() <= kResidualTolerance);
    BOOST_TEST_MESSAGE("burning + drag" << (terms.heat ? " + heat" : "") << ", largest ODE residual: moving "
                                        << std::max(moving, cloud.max()) << ", at rest " << resting);
  }
}

BOOST_AUTO_TEST_CASE(burn_agrees_with_cvode) {
  for (const Terms& terms : {kBurn, kBurnHeat}) {
    BOOST_TEST_MESSAGE("burning + drag" << (terms.heat ? " + heat" : "") << ", tau = 0.03 s:");
    cvode_distances(exact::burn, physics_with(terms), small_cloud_with_rest(), 0.03);
  }
}

// ---- The seed's published forms (docs/model.md §9) --------------------------------------------------------

BOOST_AUTO_TEST_CASE(seed_eq23_fails_and_spec_4_3_passes) {
  const Physics physics = physics_with(Terms{.drag = true});
  double smallest = 1e300;
  for (const ParticleState& y0 : sample_particles()) {
    if (y0[VX] == 0.0 && y0[VY] == 0.0 && y0[VZ] == 0.0) {
      BOOST_TEST(std::isnan(exact::seed_drag_eq23(physics, y0, 1e-3)[VX]));  // î undefined at rest
      continue;
    }
    for (double tau : {0.0, 1e-5, 1e-3}) {
      const test::ParticleResidual seed = test::particle_residual(exact::seed_drag_eq23, physics, y0, tau);
      BOOST_TEST(seed.velocity >= 1e-2, "tau = " << tau << ": " << seed.velocity);
      BOOST_TEST(seed.position <= kResidualTolerance);  // x is v's integral: only momentum fails
      smallest = std::min(smallest, seed.max());
      checked_residual(exact::drag, physics, y0, tau);
    }
  }
  BOOST_TEST_MESSAGE("seed eq. 23: smallest ODE residual " << smallest);
}

BOOST_AUTO_TEST_CASE(seed_eq26_fails_and_spec_4_4_passes) {
  const Physics physics = physics_with(kVertical);
  double smallest = 1e300, smallest_superposed = 1e300;
  // The lattice's moving particles (any direction) and the vertical ones.
  std::vector<ParticleState> list = sample_particles();
  for (const ParticleState& y0 : vertical_particles()) list.push_back(y0);
  for (const ParticleState& y0 : list) {
    if (y0[VX] == 0.0 && y0[VY] == 0.0 && y0[VZ] == 0.0) continue;
    const double s0 = std::sqrt(y0[VX] * y0[VX] + y0[VY] * y0[VY] + y0[VZ] * y0[VZ]);
    for (double tau : {0.0, 0.01 / s0, 0.1 / s0, 0.5 / s0}) {  // before eq. 23's pole at τ = 1/s0
      const test::ParticleResidual seed = test::particle_residual(exact::seed_complete_eq26, physics, y0, tau);
      BOOST_TEST(seed.velocity >= 1e-2, describe(y0) << ", tau = " << tau << ": " << seed.velocity);
      BOOST_TEST(seed.position <= kResidualTolerance);
      smallest = std::min(smallest, seed.max());
      const bool near_apex = y0[VZ] > 0.0 && std::abs(tau - exact::apex_time(physics, y0)) < 0.05;
      if (exact::vertical_motion(y0) && !near_apex) checked_residual(exact::vertical_drag_gravity, physics, y0, tau);
    }
  }
  // Superposing the corrected parts still fails, once gravity has changed the speed (g τ ≈ 2 m/s;
  // the 1 m/s particle is 0.1 s past its apex at 0.097 s).
  for (double w0 : {1.0, -1.0, -10.0}) {
    const ParticleState y0 = particle(0, 0, 5e-4, 0, 0, w0);
    const test::ParticleResidual superposed = test::particle_residual(exact::superposed_drag_gravity, physics, y0, 0.2);
    BOOST_TEST(superposed.velocity >= 1e-2, "w0 = " << w0 << ": " << superposed.velocity);
    smallest_superposed = std::min(smallest_superposed, superposed.velocity);
    checked_residual(exact::vertical_drag_gravity, physics, y0, 0.2);
  }
  BOOST_TEST_MESSAGE("seed eq. 26: smallest ODE residual " << smallest << "; drag + gravity superposed: "
                                                            << smallest_superposed);
  // t0 from the launch: x0 = v0 t0 for the lattice cloud (t0 = R_out Δ / u_s = 1e-5 s at R_out = 10).
  const ParticleState outermost = sample_particles()[4];
  const ParticleState a = exact::seed_complete_eq26(physics, outermost, 1e-3);
  const ParticleState b = exact::seed_complete_eq26_at(physics, outermost, 1e-3, 1e-5);
  for (int f = 0; f < kFields; ++f) BOOST_TEST(a[f] == b[f], tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_exact_closed_forms
