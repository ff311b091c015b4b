// The gas-parcel problem of docs/model.md §7.1 (src/problems/gas/problem.hpp) and the gas's own
// temperature updates (mpm_update.hpp):
//   - the path, the right-hand side, the closed form and the measured pressure against numbers
//     worked out here by hand from the formulas in the comments;
//   - a path through J = b' refused before integrating, with the parcel and the time;
//   - CVODE at rtol 1e-12 within 1e-10 relative of the exact adiabat, ideal and van der Waals;
//   - the corrected update is symmetric (a full period returns T_init to round-off, as the closed
//     form does) and the published one is not (its error at the period halves with Δt: order 1);
//   - the updates refuse a problem that is not gas parcels.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "problems/gas/mpm_update.hpp"
#include "problems/gas/problem.hpp"

namespace unit_gas_problem {

using namespace dlpverify;
using gas::GasProblem;
using gas::Material;

namespace {

constexpr double kAtm = 101325.0;
constexpr double kPi = std::numbers::pi;

double relative(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

Material air() { return Material::from_molar({.P0 = kAtm, .T0 = 300.0, .molar_mass = 0.02897, .gamma = 1.4}); }
Material co2_20_bar() {
  return Material::from_molar({.P0 = 2.0e6, .T0 = 300.0, .molar_mass = 0.04401, .gamma = 1.29, .a = 0.3640, .b = 4.267e-5});
}
// One parcel at T_init = T0 with J_min = 0.3 and period 1 ms.
GasProblem one_parcel(const Material& gas) {
  return GasProblem("one", gas, {.parcels = 1, .j_min_low = 0.3, .j_min_high = 0.3, .period = 1e-3, .temperature_spread = 0.0});
}

// A problem that is not gas parcels: dy/dt = −y.
class Decay final : public Problem {
 public:
  std::string name() const override { return "decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  std::vector<Variable> variables() const override { return {{"y", 0, 1, "1"}}; }
  Eigen::Index members() const override { return 1; }
  double initial_time() const override { return 0.0; }
  State initial_state() const override { return State::Ones(1, 1); }
  void rhs(double, Eigen::Index, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = -y[0][i];
  }
};

double advance_one(const std::string& update, const GasProblem& problem, double duration, long steps) {
  State state = problem.initial_state();
  gas::make_temperature_update(update)->advance(problem, state, 0.0, duration / static_cast<double>(steps), steps);
  return state(0, 0);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(gas_problem)

BOOST_AUTO_TEST_CASE(path_right_hand_side_closed_form_and_pressure_by_hand) {
  const GasProblem ideal = one_parcel(air());
  // J(τ) = 1 − (1 − J_min) sin²(πτ/P): at P/4, 1 − 0.7/2 = 0.65; at P/2, J_min; at P, 1.
  BOOST_TEST(relative(ideal.path(0).J(0.25e-3), 0.65) < 1e-15);
  BOOST_TEST(relative(ideal.path(0).J(0.5e-3), 0.3) < 1e-15);
  BOOST_TEST(std::abs(ideal.path(0).J(1e-3) - 1.0) < 1e-15);
  // dT/dt = −(γ − 1) T J̇/J with J̇(P/4) = −0.7 π/P: 0.4 · 300 · 0.7π/1e-3/0.65 K/s.
  const double y = 300.0;
  double rate = 0.0;
  const double* in[] = {&y};
  double* out[] = {&rate};
  ideal.rhs(0.25e-3, 0, 1, in, out);
  BOOST_TEST(relative(rate, 0.4 * 300.0 * 0.7 * kPi / 1e-3 / 0.65) < 1e-14);
  // T(P/2) = 300 · 0.3^(−0.4) = 300 · 1.6186445827673461 (computed apart), P = P0 (T/T0)/J.
  const State T = closed_form(ideal, ideal.initial_state(), 0.5e-3);
  BOOST_TEST(relative(T(0, 0), 300.0 * 1.6186445827673461) < 1e-14);
  const State measured = ideal.measured(T, 0.5e-3);
  BOOST_TEST(relative(measured(0, 1), kAtm * 1.6186445827673461 / 0.3) < 1e-14);
  // van der Waals: P(J = 1, T0) = P0 (docs/model.md §7.1), the parcel's start.
  const GasProblem vdw = one_parcel(co2_20_bar());
  BOOST_TEST(relative(vdw.measured(vdw.initial_state(), 0.0)(0, 1), 2.0e6) < 1e-13);
}

BOOST_AUTO_TEST_CASE(population_spreads_j_min_and_temperature) {
  const GasProblem p("spread", air(), {.parcels = 5, .j_min_low = 0.3, .j_min_high = 0.9, .period = 1e-3, .temperature_spread = 0.1});
  const Eigen::ArrayXd j = p.deepest_compression();
  BOOST_TEST(j[0] == 0.3);
  BOOST_TEST(relative(j[2], 0.6) < 1e-15);
  BOOST_TEST(j[4] == 0.9);
  const State T = p.initial_state();
  BOOST_TEST(T.minCoeff() >= 270.0);
  BOOST_TEST(T.maxCoeff() <= 330.0);
  BOOST_TEST(T(0, 0) == 270.0);  // parcel 0: shuffled fraction 0, T0 (1 − 0.1)
}

// A rank's parcels under mpirun come from their indices alone (docs/mpi.md): two billion parcels
// hold nothing per parcel (a whole population's paths and temperatures would be 48 GB), and the
// middle one, p = 10⁹ of N = 2·10⁹ + 1, sits at s = 1/2 of [J_min low, high]: J_min = 0.6.
BOOST_AUTO_TEST_CASE(parcels_come_from_their_indices_alone) {
  const GasProblem p("many", air(), {.parcels = 2'000'000'001, .j_min_low = 0.3, .j_min_high = 0.9, .period = 1e-3,
                                     .temperature_spread = 0.1});
  BOOST_TEST(p.members() == 2'000'000'001);
  BOOST_TEST(relative(p.path(1'000'000'000).j_min, 0.6) < 1e-15);
  BOOST_TEST(p.path(2'000'000'000).j_min == 0.9);
  const State T = p.initial_members(1'000'000'000, 2);
  BOOST_TEST_REQUIRE(T.rows() == 2);
  BOOST_TEST((T(0, 0) >= 270.0 && T(0, 0) <= 330.0));  // T0 (1 ± 0.1)
  BOOST_TEST(T(1, 0) == p.initial_temperature(1'000'000'001));
}

BOOST_AUTO_TEST_CASE(a_path_through_b_prime_is_refused_with_parcel_and_time) {
  const Material dense = Material::from_reduced({.P0 = kAtm, .T0 = 300.0, .rho0 = 1.0, .gamma = 1.4, .b_prime = 0.5});
  const GasProblem p = one_parcel(dense);
  BOOST_CHECK_NO_THROW(p.check_paths(0.2e-3));  // J(0.2 ms) = 1 − 0.7 sin²(0.2π) = 0.758 > 0.5
  try {
    p.check_paths(0.75e-3);
    BOOST_FAIL("a path through J = b' was accepted");
  } catch (const InputError& e) {
    const std::string what = e.what();
    BOOST_TEST(what.find("parcel 0") != std::string::npos);
    // sin²(πt/P) = (1 − 0.5)/(1 − 0.3): t = P/π asin(√(5/7)) = 0.000320491482014312 s (computed apart).
    BOOST_TEST(what.find("0.00032049148201") != std::string::npos, what);
  }
}

BOOST_AUTO_TEST_CASE(cvode_at_rtol_1e_12_is_within_1e_10_of_the_exact_adiabat) {
  for (const Material& gas : {air(), co2_20_bar()}) {
    const GasProblem p("population", gas, {});
    const State initial = p.initial_state();
    ReferenceSettings settings;
    settings.rtol = 1e-12;
    nlohmann::json statistics;
    const State cvode = solve_with_cvode(p, initial, 0.0, 0.75e-3, settings, statistics);
    const State exact = closed_form(p, initial, 0.75e-3);
    BOOST_TEST(((cvode - exact).abs() / exact.abs()).maxCoeff() <= 1e-10);
  }
}

BOOST_AUTO_TEST_CASE(the_corrected_update_is_symmetric_the_published_one_first_order) {
  for (const Material& gas : {air(), co2_20_bar()}) {
    const GasProblem p = one_parcel(gas);
    // The closed form returns to T_init = 300 K after a full period (J is back at 1).
    BOOST_TEST(relative(advance_one("mpm-trapezoid-corrected", p, 1e-3, 64), 300.0) < 1e-13);
    const double coarse = advance_one("mpm-trapezoid", p, 1e-3, 64) - 300.0;
    const double fine = advance_one("mpm-trapezoid", p, 1e-3, 128) - 300.0;
    BOOST_TEST(std::abs(coarse) > 1e-3);              // a real error, not round-off
    BOOST_TEST(std::abs(coarse / fine - 2.0) < 0.05);  // first order: halving Δt halves it
  }
}

BOOST_AUTO_TEST_CASE(the_updates_refuse_a_problem_that_is_not_gas) {
  const Decay decay;
  State state = decay.initial_state();
  BOOST_CHECK_THROW(gas::make_temperature_update("mpm-trapezoid")->advance(decay, state, 0.0, 0.1, 1), InputError);
  BOOST_TEST(gas::make_temperature_update("rk2") == nullptr);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_gas_problem
