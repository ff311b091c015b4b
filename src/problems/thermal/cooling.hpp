// A population of hot particles cooling by convection and radiation as a dlpverify Problem
// (docs/model.md §7.3): the seed's lumped thermal model after impact,
//   m C dθ/dt = −h_c a_s (θ − θ_o) − ε σ a_s (θ⁴ − θ_s⁴),
// each particle with its own diameter d, emissivity ε and initial temperature θ0, so that for a
// sphere a_s/(m C) = 6/(ρ C d): α = 6 h_c/(ρ C d), β = 6 ε σ/(ρ C d). The one field is T (= θ).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/splitting.hpp"
#include "dlpverify/exchange_description.hpp"
#include "harness/distribution.hpp"
#include "dlpverify/initial_members.hpp"

namespace dlpverify::thermal {

inline constexpr double kStefanBoltzmann = 5.67e-8;  // σ [W/(m² K⁴)], the seed's value

struct CoolingPhysics {
  double h_c = 100.0;                 // convection coefficient [W/(m² K)]
  double theta_gas = 300.0;           // θ_o [K]
  double theta_surroundings = 300.0;  // θ_s [K]
  double density = 2700.0;            // ρ [kg/m³]
  double heat_capacity = 900.0;       // C [J/(kg K)]
};

// How the particles differ: particle p of N takes each quantity at its own point of the range, on
// three interleaved low-discrepancy sequences (so that size, emissivity and temperature are not
// correlated).
struct CoolingPopulation {
  int particles = 1000;
  double d_min = 50e-6, d_max = 200e-6;   // [m]
  double emissivity_min = 0.3, emissivity_max = 0.9;
  double theta0_min = 800.0, theta0_max = 1500.0;  // [K]
};

// Capabilities: the linear decay, the closed form where the physics has one, parameters and
// diagnostics, the exchange description, and particles built alone (a rank's share under mpirun).
// A particle's α, β and θ0 are computed from its index; the right-hand side reads α and β from
// memory for the `held` particles (a rank's own under mpirun), and computes any other's.
class CoolingProblem final : public Problem,
                             public ClosedForm,
                             public LinearDecay,
                             public CaseReport,
                             public MemberNoun,
                             public ExchangeDescription,
                             public InitialMembers {
 public:
  // `held`: the particles whose α and β are kept (every particle when not given).
  CoolingProblem(std::string case_name, const CoolingPhysics& physics, const CoolingPopulation& population,
                 std::optional<MemberRange> held = std::nullopt);

  std::string name() const override { return case_name_; }
  MemberNouns member_nouns() const override { return {"particle", "particles"}; }
  std::vector<Field> fields() const override { return {{"T", "K"}}; }
  std::vector<Variable> variables() const override { return {{"temperature", 0, 1, "K"}}; }
  Eigen::Index members() const override { return population_.particles; }
  double initial_time() const override { return 0.0; }
  State initial_state() const override { return initial_members(0, members()); }
  // Particles first … first + count − 1 alone: their initial temperatures θ0.
  State initial_members(Eigen::Index first, Eigen::Index count) const override;

  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override;
  // Convection is the linear decay α (the seed's eq. 7.30 keeps it in the denominator).
  void linear_decay(Eigen::Index first, int count, double* const* lambda) const override;

  // With h_c = 0 (radiation only), or with θ_o = θ_s = 0 (Bernoulli).
  State solution(Eigen::Index first, const State& initial, double tau) const override;
  std::string formula() const override;

  nlohmann::json parameters() const override;
  // For a program outside dlpverify: θ_o, θ_s, and each particle's α and β (docs/exchange.md).
  ProblemDescription description() const override;
  std::vector<MemberReduction> diagnostic_reductions() const override;
  Eigen::ArrayXXd member_terms(Eigen::Index first, const State& initial, const State& finest, double t_end) const override;
  nlohmann::json diagnostics(const std::vector<double>& reduced, double t_end) const override;

  // Particle p's rates: α = 6 h_c/(ρ C d) [1/s] and β = 6 ε σ/(ρ C d) [1/(s K³)], with its diameter
  // d at its point (p + ½)/N of [d_min, d_max] and ε on a golden-ratio sequence.
  struct Rates {
    double alpha, beta;
  };
  Rates rates(Eigen::Index p) const;
  // Particle p's initial temperature θ0 [K], on a silver-ratio sequence over [θ0_min, θ0_max].
  double theta0(Eigen::Index p) const;

 private:
  enum class Exact { none, radiation, radiation_to_vacuum, bernoulli };
  Exact closed_form_kind() const;
  // α and β of particles first … first + count − 1: the held ones' in memory, any other's
  // computed into `scratch`.
  std::pair<const double*, const double*> rates_of(Eigen::Index first, int count, std::vector<double>& scratch) const;

  std::string case_name_;
  CoolingPhysics physics_;
  CoolingPopulation population_;
  MemberRange held_;
  std::vector<double> alpha_, beta_;  // of the held particles [1/s], [1/(s K³)]
};

}  // namespace dlpverify::thermal
