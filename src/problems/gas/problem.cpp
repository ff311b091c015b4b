#include "problems/gas/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"

namespace dlpverify::gas {

void Population::validate() const {
  if (parcels < 1) throw InputError("parcels", std::to_string(parcels), "must be at least 1");
  auto inside_unit = [](const char* quantity, double j) {
    if (!std::isfinite(j) || j <= 0.0 || j >= 1.0)
      throw InputError(quantity, value_text(j), "must lie in (0, 1): a compression to that volume ratio");
  };
  inside_unit("deepest compression J_min, low end", j_min_low);
  inside_unit("deepest compression J_min, high end", j_min_high);
  if (j_min_low > j_min_high)
    throw InputError("deepest compression J_min, low end", value_text(j_min_low),
                     "is above the high end " + value_text(j_min_high));
  if (!std::isfinite(period) || period <= 0.0) throw InputError("path period", value_text(period), "must be positive and finite");
  if (!std::isfinite(temperature_spread) || temperature_spread < 0.0 || temperature_spread >= 1.0)
    throw InputError("initial temperature spread", value_text(temperature_spread), "must lie in [0, 1)");
}

GasProblem::GasProblem(std::string case_name, const Material& gas, const Population& population)
    : case_name_(std::move(case_name)), gas_(gas), population_(population) {
  population.validate();
  provide<ClosedForm>(*this);
  provide<TimeScale>(*this);
  provide<CaseReport>(*this);
  provide<MemberNoun>(*this);
  provide<ExchangeDescription>(*this);
  provide<InitialMembers>(*this);
}

CompressionPath GasProblem::path(Eigen::Index p) const {
  const int n = population_.parcels;
  const double along = n > 1 ? static_cast<double>(p) / (n - 1) : 0.0;
  // (1 − s) low + s high: both ends exact.
  return {(1.0 - along) * population_.j_min_low + along * population_.j_min_high, population_.period};
}

double GasProblem::initial_temperature(Eigen::Index p) const {
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  // A shuffled fraction in [0, 1) (p times the golden ratio, mod 1): T_init uncorrelated with J_min.
  const double shuffled = std::fmod(static_cast<double>(p) * golden, 1.0);
  return gas_.T0() * (1.0 - population_.temperature_spread * (1.0 - 2.0 * shuffled));
}

State GasProblem::initial_members(Eigen::Index first, Eigen::Index count) const {
  State state(count, 1);
  for (Eigen::Index p = 0; p < count; ++p) state(p, 0) = initial_temperature(first + p);
  return state;
}

// dT/dt = (dT/dJ)(J) J̇, with dT/dJ the material's adiabat (one formula: Material::adiabat_slope).
void GasProblem::rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const {
  const double tau = t - initial_time();
  for (int i = 0; i < count; ++i) {
    const CompressionPath c = path(first + i);
    dydt[0][i] = gas_.adiabat_slope(c.J(tau), y[0][i]) * c.rate(tau);
  }
}

State GasProblem::measured(State state, double tau, Eigen::Index first) const {
  State columns(state.rows(), 2);
  for (Eigen::Index p = 0; p < state.rows(); ++p) {
    columns(p, 0) = state(p, 0);
    columns(p, 1) = gas_.pressure(path(first + p).J(tau), state(p, 0));
  }
  return columns;
}

State GasProblem::solution(Eigen::Index first, const State& initial, double tau) const {
  State state(initial.rows(), 1);
  for (Eigen::Index p = 0; p < initial.rows(); ++p)
    state(p, 0) = gas_.adiabat_temperature(initial(p, 0), path(first + p).J(tau));
  return state;
}

// The path's own time scale P/(2π), or the adiabat's |T/Ṫ| = (J − b')/((γ − 1)|J̇|) where it is faster.
double GasProblem::time_scale(Eigen::Index member, const double* /*y*/, double tau) const {
  const CompressionPath c = path(member);
  const double path_scale = c.period / (2.0 * std::numbers::pi);
  const double rate = std::abs(c.rate(tau));
  if (rate == 0.0) return path_scale;
  return std::min(path_scale, (c.J(tau) - gas_.b_prime()) / ((gas_.gamma() - 1.0) * rate));
}

void GasProblem::check_paths(double duration) const {
  for (Eigen::Index p = 0; p < members(); ++p) {
    const CompressionPath c = path(p);
    if (c.smallest_J(duration) > gas_.b_prime()) continue;
    throw InputError("deepest compression J_min, low end", value_text(population_.j_min_low),
                     "parcel " + std::to_string(p) + " (J_min = " + value_text(c.j_min) + ") reaches J = b' = " +
                         value_text(gas_.b_prime()) + " at t = " + value_text(c.time_to_reach(gas_.b_prime())) +
                         " s: the molecules' own volume cannot be compressed");
  }
}

Eigen::ArrayXd GasProblem::deepest_compression() const {
  Eigen::ArrayXd j(members());
  for (Eigen::Index p = 0; p < members(); ++p) j[p] = path(p).j_min;
  return j;
}

nlohmann::json GasProblem::parameters() const {
  return {{"gas", gas_.is_van_der_waals() ? "van der Waals" : "ideal"},
          {"P0", gas_.P0()}, {"T0", gas_.T0()}, {"gamma", gas_.gamma()}, {"rho0", gas_.rho0()},
          {"a_prime", gas_.a_prime()}, {"b_prime", gas_.b_prime()}, {"P0_prime", gas_.P0_prime()},
          {"Cv", gas_.Cv()}, {"parcels", population_.parcels}, {"j_min_low", population_.j_min_low},
          {"j_min_high", population_.j_min_high}, {"period", population_.period},
          {"temperature_spread", population_.temperature_spread}};
}

ProblemDescription GasProblem::description() const {
  return {"gas",
          {{"P0", gas_.P0(), "Pa"}, {"T0", gas_.T0(), "K"}, {"gamma", gas_.gamma(), "1"}, {"rho0", gas_.rho0(), "kg/m^3"},
           {"a_prime", gas_.a_prime(), "Pa"}, {"b_prime", gas_.b_prime(), "1"}, {"P0_prime", gas_.P0_prime(), "Pa"},
           {"Cv", gas_.Cv(), "J/(kg K)"}, {"parcels", static_cast<double>(population_.parcels), "1"},
           {"j_min_low", population_.j_min_low, "1"}, {"j_min_high", population_.j_min_high, "1"},
           {"period", population_.period, "s"}, {"temperature_spread", population_.temperature_spread, "1"}},
          {{"gas", gas_.is_van_der_waals() ? "van der Waals" : "ideal"}},
          {{{"j_min", "1"}, deepest_compression()}}};  // each parcel's path J(τ) = 1 − (1 − J_min) sin²(π τ/P)
}

// The compression the study reached: the smallest J over the parcels at the end, and the range of
// the finest level's temperatures and pressures. Each parcel's terms: J_min, T, T, p, p.
std::vector<MemberReduction> GasProblem::diagnostic_reductions() const {
  return {MemberReduction::min, MemberReduction::min, MemberReduction::max, MemberReduction::min, MemberReduction::max};
}

Eigen::ArrayXXd GasProblem::member_terms(Eigen::Index first, const State& /*initial*/, const State& finest,
                                         double t_end) const {
  const State m = measured(finest, t_end, first);
  Eigen::ArrayXXd terms(finest.rows(), 5);
  for (Eigen::Index p = 0; p < finest.rows(); ++p) terms(p, 0) = path(first + p).smallest_J(t_end);
  terms.col(1) = m.col(0);
  terms.col(2) = m.col(0);
  terms.col(3) = m.col(1);
  terms.col(4) = m.col(1);
  return terms;
}

nlohmann::json GasProblem::diagnostics(const std::vector<double>& reduced, double /*t_end*/) const {
  return {{"smallest_J_reached", reduced[0]},
          {"temperature_range_K", {reduced[1], reduced[2]}},
          {"pressure_range_Pa", {reduced[3], reduced[4]}}};
}

}  // namespace dlpverify::gas
