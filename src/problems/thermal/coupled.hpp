// The seed's semi-analytic coupled systems for staggering (docs/model.md §7.3), as Problems:
//   2 × 2:  a ẇ1 + w2 = 0,  b ẇ2 + w1 = 0
//   3 × 3:  a ẇ1 + w2 = 0,  b ẇ2 + w3 = 0,  c ẅ3 + w1 = 0   (fields w1, w2, w3, v3 = ẇ3)
// over a population of initial conditions. The second-order equation's value and rate form one
// staggered block, so that backward Euler on (w3, v3) is the seed's second difference
// (w3^{L+1} − 2 w3^L + w3^{L−1})/Δt² and a Jacobi sweep is the seed's iteration, whose spectral
// radius is Δt/√(ab) (2 × 2) and (Δt⁴/|abc|)^{1/3} (3 × 3).
#pragma once

#include <string>
#include <vector>

#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/solution_features.hpp"
#include "dlpverify/splitting.hpp"
#include "dlpverify/exchange_description.hpp"
#include "dlpverify/initial_members.hpp"

namespace dlpverify::thermal {

struct CouplingConstants {
  double a = 2.0, b = 0.5, c = 1.0;  // √(ab) = 1 and |abc|^{1/4} = 1 by default
};

// Capabilities: the staggered blocks and their sweeps' spectral radii, the closed form, its time
// scale, parameters, the exchange description, a dimensionless time, and members built alone (a
// rank's share under mpirun).
class CoupledSystem final : public Problem,
                            public StaggeredBlocks,
                            public SweepContraction,
                            public ClosedForm,
                            public TimeScale,
                            public CaseReport,
                            public MemberNoun,
                            public ExchangeDescription,
                            public TimeUnit,
                            public InitialMembers {
 public:
  // equations: 2 or 3.
  CoupledSystem(std::string case_name, int equations, const CouplingConstants& constants, int members = 8);

  std::string name() const override { return case_name_; }
  MemberNouns member_nouns() const override { return {"system", "systems"}; }
  std::vector<Field> fields() const override;
  std::vector<Variable> variables() const override;
  Eigen::Index members() const override { return members_; }
  double initial_time() const override { return 0.0; }
  State initial_state() const override { return initial_members(0, members_); }
  State initial_members(Eigen::Index first, Eigen::Index count) const override;
  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override;
  std::vector<FieldBlock> staggered_blocks() const override;

  // 2 × 2: w1 = w1(0) cosh ωt − w2(0) √(b/a) sinh ωt, w2 = w2(0) cosh ωt − w1(0) √(a/b) sinh ωt,
  // ω = 1/√(ab). 3 × 3: y(t) = exp(A t) y(0), the matrix exponential of the 4 × 4 system (Eigen's
  // MatrixFunctions, Padé with scaling and squaring).
  State solution(Eigen::Index first, const State& initial, double tau) const override;
  std::string formula() const override;
  // 1/|λ| of the system's eigenvalues, the same for every member: λ = ±1/√(ab) (2 × 2) and
  // λ⁴ = −1/(abc) (3 × 3), so √(ab) and |abc|^{1/4}, the step limit. The generic |y_f / f_f| would
  // take a member whose field passes near zero for a fast one.
  double time_scale(Eigen::Index, const double*, double) const override { return step_limit(); }
  nlohmann::json parameters() const override;
  std::vector<MemberReduction> diagnostic_reductions() const override { return {}; }  // no diagnostics
  Eigen::ArrayXXd member_terms(Eigen::Index, const State& initial, const State&, double) const override {
    return Eigen::ArrayXXd(initial.rows(), 0);
  }
  nlohmann::json diagnostics(const std::vector<double>&, double) const override { return nlohmann::json::object(); }
  std::string time_unit() const override { return "1"; }
  ProblemDescription description() const override;  // a, b, c and the equations, for docs/exchange.md

  // The spectral radius of a Jacobi sweep at step dt, and of a Gauss–Seidel sweep (its square for
  // the 2 × 2, its 3/2 power for the 3 × 3: both couplings are cyclic), and the largest step at which
  // they converge: √(ab), |abc|^{1/4}.
  double jacobi_radius(double dt) const override;
  double gauss_seidel_radius(double dt) const override;
  double step_limit() const override;
  std::string jacobi_radius_formula() const override;        // "dt/sqrt(ab)", …
  std::string gauss_seidel_radius_formula() const override;  // "dt^2/(ab)", …
  std::string step_limit_formula() const override;           // "sqrt(ab)", "|abc|^(1/4)"
  // The exponent p of ρ ∝ Δt^p: 1 (2 × 2), 4/3 (3 × 3).
  double radius_exponent() const override { return equations_ == 2 ? 1.0 : 4.0 / 3.0; }

 private:
  std::string case_name_;
  int equations_;
  CouplingConstants k_;
  Eigen::Index members_;
};

}  // namespace dlpverify::thermal
