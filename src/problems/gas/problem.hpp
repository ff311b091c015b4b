// Gas parcels on prescribed compression paths as a dlpverify Problem (docs/model.md §7.1).
//
// N parcels of one gas (ideal or van der Waals), parcel p with its own initial temperature and its
// own path J_p(t) (path.hpp). The one field is T; the adiabat
//   dT/dt = (dT/dJ) J̇ = −(γ − 1) T J̇/(J − b')
// is the right-hand side, and its closed form T = T_init ((1 − b')/(J − b'))^(γ − 1) the reference.
// Measured: temperature and the pressure P(J, T) the temperature implies.
#pragma once

#include <string>
#include <vector>

#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/solution_features.hpp"
#include "dlpverify/exchange_description.hpp"
#include "dlpverify/initial_members.hpp"
#include "problems/gas/material.hpp"
#include "problems/gas/path.hpp"

namespace dlpverify::gas {

// How the parcels differ: parcel p of N has J_min spread evenly over [j_min_low, j_min_high] and an
// initial temperature spread over T0 × [1 − spread, 1 + spread] in a shuffled order (so that J_min
// and T_init are not correlated).
struct Population {
  int parcels = 400;
  double j_min_low = 0.3;
  double j_min_high = 0.9;
  double period = 1e-3;             // every path's period P [s]
  double temperature_spread = 0.2;  // initial temperatures T0 (1 ± spread)

  // Throws InputError naming the quantity for a count below 1, J_min outside (0, 1), low > high,
  // a non-positive period or a spread outside [0, 1).
  void validate() const;
};

// Capabilities: the closed form, time scales, parameters and diagnostics, the exchange description,
// and parcels built alone (a rank's share under mpirun). A parcel's path and initial temperature
// are computed from its index when asked, never held: no process holds the whole population's.
class GasProblem final : public Problem,
                         public ClosedForm,
                         public TimeScale,
                         public CaseReport,
                         public MemberNoun,
                         public ExchangeDescription,
                         public InitialMembers {
 public:
  GasProblem(std::string case_name, const Material& gas, const Population& population);

  std::string name() const override { return case_name_; }
  MemberNouns member_nouns() const override { return {"parcel", "parcels"}; }
  std::vector<Field> fields() const override { return {{"T", "K"}}; }
  std::vector<Variable> variables() const override {
    return {{"temperature", 0, 1, "K"}, {"pressure", 1, 1, "Pa"}};  // pressure: measured column 1
  }
  State measured(State state, double tau, Eigen::Index first = 0) const override;

  Eigen::Index members() const override { return population_.parcels; }
  double initial_time() const override { return 0.0; }
  State initial_state() const override { return initial_members(0, members()); }
  // Parcels first … first + count − 1 alone: their initial temperatures.
  State initial_members(Eigen::Index first, Eigen::Index count) const override;

  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override;

  State solution(Eigen::Index first, const State& initial, double tau) const override;
  std::string formula() const override {
    return "docs/model.md §7.1: T = T_init ((1 - b')/(J - b'))^(gamma - 1)";
  }
  double time_scale(Eigen::Index member, const double* y, double tau) const override;

  nlohmann::json parameters() const override;
  ProblemDescription description() const override;
  std::vector<MemberReduction> diagnostic_reductions() const override;
  Eigen::ArrayXXd member_terms(Eigen::Index first, const State& initial, const State& finest, double t_end) const override;
  nlohmann::json diagnostics(const std::vector<double>& reduced, double t_end) const override;

  // Refuses a study whose paths reach J ≤ b' within `duration`, naming the first such parcel and
  // the time it gets there (InputError).
  void check_paths(double duration) const;

  const Material& material() const { return gas_; }
  // Parcel p's path: J_min at its point p/(N − 1) of [j_min_low, j_min_high].
  CompressionPath path(Eigen::Index p) const;
  // Parcel p's initial temperature T0 (1 − spread (1 − 2 s)), s = frac(p g) with g the golden ratio.
  double initial_temperature(Eigen::Index p) const;
  // Each parcel's deepest compression J_min: where in the population an error lives.
  Eigen::ArrayXd deepest_compression() const;

 private:
  std::string case_name_;
  Material gas_;
  Population population_;
};

}  // namespace dlpverify::gas
