// The cooling problem of docs/model.md §7.3 (src/problems/thermal) and the seed's implicit update:
//   - the three closed forms against numbers worked out here: a hand value, and an independent
//     integration of the ODE (classical RK4 at 20,000 steps, written here);
//   - the right-hand side of one particle against the formula evaluated by hand;
//   - implicit-fp's step against the seed's eq. 7.30 solved here by Newton's method, its iteration
//     count, and its refusal (SolverError) of a step at which the iteration diverges.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "integrators/implicit/fixed_point.hpp"
#include "problems/thermal/cooling.hpp"
#include "problems/thermal/cooling_exact.hpp"

namespace unit_thermal {

using namespace dlpverify;
using namespace dlpverify::thermal;

namespace {

double relative(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// θ(t) of dθ/dt = rate(θ) by classical RK4 with n steps (independent of the library).
double rk4(const std::function<double(double)>& rate, double theta, double t, int n = 20000) {
  const double h = t / n;
  for (int i = 0; i < n; ++i) {
    const double k1 = rate(theta), k2 = rate(theta + 0.5 * h * k1), k3 = rate(theta + 0.5 * h * k2),
                 k4 = rate(theta + h * k3);
    theta += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return theta;
}

// One 100 µm particle, ε = 0.5, at 1000 K: α = 6 h_c/(ρ C d), β = 6 ε σ/(ρ C d), ρ C d = 243 J/(m² K).
CoolingProblem one_particle(double h_c, double theta_o, double theta_s) {
  CoolingPhysics physics;
  physics.h_c = h_c;
  physics.theta_gas = theta_o;
  physics.theta_surroundings = theta_s;
  return CoolingProblem("one", physics, CoolingPopulation{1, 1e-4, 1e-4, 0.5, 0.5, 1000.0, 1000.0});
}

}  // namespace

BOOST_AUTO_TEST_SUITE(thermal_cooling)

BOOST_AUTO_TEST_CASE(radiation_to_vacuum_by_hand) {
  // θ0 = 1000 K, β = 1e-9 /(s K³), t = 1 s: 1 + 3 β θ0³ t = 4, θ = 1000 / 4^(1/3)
  BOOST_TEST(relative(radiation_to_vacuum(1000.0, 1e-9, 1.0), 629.9605249474366) < 1e-14);
}

BOOST_AUTO_TEST_CASE(closed_forms_match_an_independent_integration) {
  const double beta = 2.5e-9, alpha = 3.0, t = 0.4;
  const double surroundings = radiation_to_surroundings(1400.0, beta, 300.0, t);
  const double reference_s = rk4([&](double th) { return -beta * (std::pow(th, 4) - std::pow(300.0, 4)); }, 1400.0, t);
  BOOST_TEST(relative(surroundings, reference_s) < 1e-12);
  // heated by warmer surroundings: the root lies above θ0
  const double heated = radiation_to_surroundings(300.0, beta, 1400.0, t);
  const double reference_h = rk4([&](double th) { return -beta * (std::pow(th, 4) - std::pow(1400.0, 4)); }, 300.0, t);
  BOOST_TEST(relative(heated, reference_h) < 1e-12);
  const double bernoulli = convection_and_radiation_to_zero(1400.0, alpha, beta, t);
  const double reference_b = rk4([&](double th) { return -alpha * th - beta * std::pow(th, 4); }, 1400.0, t);
  BOOST_TEST(relative(bernoulli, reference_b) < 1e-12);
  const double vacuum = radiation_to_vacuum(1400.0, beta, t);
  BOOST_TEST(relative(vacuum, rk4([&](double th) { return -beta * std::pow(th, 4); }, 1400.0, t)) < 1e-12);
}

BOOST_AUTO_TEST_CASE(right_hand_side_by_hand) {
  const CoolingProblem p = one_particle(100.0, 300.0, 300.0);
  const double alpha = 600.0 / 243.0, beta = 0.5 * 5.67e-8 * 6.0 / 243.0;
  const double theta = 1000.0, expected = -alpha * 700.0 - beta * (1e12 - 8.1e9);
  double y = theta, dydt = 0.0;
  const double* in[] = {&y};
  double* out[] = {&dydt};
  p.rhs(0.0, 0, 1, in, out);
  BOOST_TEST(relative(dydt, expected) < 1e-14);
  double lambda = 0.0;
  double* decay[] = {&lambda};
  p.linear_decay(0, 1, decay);
  BOOST_TEST(relative(lambda, alpha) < 1e-15);
  BOOST_TEST(!has_closed_form(p));
  BOOST_TEST(has_closed_form(one_particle(0.0, 300.0, 300.0)));
  BOOST_TEST(has_closed_form(one_particle(100.0, 0.0, 0.0)));
}

BOOST_AUTO_TEST_CASE(implicit_step_solves_the_seeds_update) {
  // eq. 7.30 per unit m C: θ1 (1 + α Δt) = θ0 + α Δt θ_o − Δt β (θ1⁴ − θ_s⁴), by Newton here.
  const CoolingProblem p = one_particle(100.0, 300.0, 300.0);
  const double alpha = 600.0 / 243.0, beta = 0.5 * 5.67e-8 * 6.0 / 243.0, dt = 0.05, theta0 = 1000.0;
  double theta1 = theta0;
  for (int i = 0; i < 50; ++i) {
    const double g = theta1 * (1.0 + alpha * dt) - theta0 - alpha * dt * 300.0 + dt * beta * (std::pow(theta1, 4) - std::pow(300.0, 4));
    theta1 -= g / (1.0 + alpha * dt + 4.0 * dt * beta * std::pow(theta1, 3));
  }
  implicit::FixedPointEuler fp;
  State state = p.initial_state();
  fp.advance(p, state, 0.0, dt, 1);
  BOOST_TEST(relative(state(0, 0), theta1) < 1e-12);
  // The correction contracts by Δt 4βθ³/(1 + αΔt) ≈ 0.125 per iteration at 1000 K (less as θ falls)
  // from the first, Δt |f| ≈ 120 K = 0.12 of θ's size: 0.12 × 0.125^(k−1) ≤ 1e-12 takes k ≤ 14.
  const int iterations = static_cast<int>(fp.statistics().extra_count("iterations").value());
  BOOST_TEST(iterations >= 10);
  BOOST_TEST(iterations <= 14);
}

BOOST_AUTO_TEST_CASE(diverging_iteration_is_reported) {
  CoolingPhysics physics;
  physics.h_c = 0.0;
  const CoolingProblem p("hot", physics, CoolingPopulation{1, 1e-4, 1e-4, 0.9, 0.9, 3000.0, 3000.0});
  implicit::FixedPointEuler fp;
  State state = p.initial_state();
  BOOST_CHECK_THROW(fp.advance(p, state, 0.0, 1.0, 1), SolverError);
}

// A rank's particles under mpirun come from their indices alone (docs/mpi.md): of two billion
// particles a rank keeps the rates of its own block only (the whole population's α, β and θ0
// would be 48 GB). The middle one, p = 10⁹ of N = 2·10⁹ + 1, has d = (d_min + d_max)/2 = 125 µm:
// α = 6 h_c/(ρ C d) = 600/303.75 1/s. Held or computed, a particle's rates are the same bits.
BOOST_AUTO_TEST_CASE(particles_come_from_their_indices_alone) {
  const CoolingPopulation many{2'000'000'001, 50e-6, 200e-6, 0.3, 0.9, 800.0, 1500.0};
  const CoolingProblem held("many", CoolingPhysics{}, many, MemberRange{1'000'000'000, 4096});
  const CoolingProblem none("many", CoolingPhysics{}, many, MemberRange{0, 0});
  BOOST_TEST(held.members() == 2'000'000'001);
  BOOST_TEST(relative(held.rates(1'000'000'000).alpha, 600.0 / 303.75) < 1e-14);
  for (const Eigen::Index first : {Eigen::Index{1'000'000'000}, Eigen::Index{1'000'004'000}}) {  // held; half held
    double lambda[2][200], theta[200], rate[2][200];
    double* lambdas[2] = {lambda[0], lambda[1]};
    held.linear_decay(first, 200, &lambdas[0]);
    none.linear_decay(first, 200, &lambdas[1]);
    for (int i = 0; i < 200; ++i) theta[i] = 900.0 + i;
    const double* y[] = {theta};
    double* dydt[2][1] = {{rate[0]}, {rate[1]}};
    held.rhs(0.0, first, 200, y, dydt[0]);
    none.rhs(0.0, first, 200, y, dydt[1]);
    for (int i = 0; i < 200; ++i) {
      BOOST_TEST(lambda[0][i] == held.rates(first + i).alpha);
      BOOST_TEST(lambda[1][i] == lambda[0][i]);
      BOOST_TEST(rate[1][i] == rate[0][i]);
    }
  }
  const State theta0 = none.initial_members(1'999'999'999, 2);
  BOOST_TEST_REQUIRE(theta0.rows() == 2);
  BOOST_TEST((theta0.minCoeff() >= 800.0 && theta0.maxCoeff() <= 1500.0));
  BOOST_TEST(theta0(1, 0) == none.theta0(2'000'000'000));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_thermal
