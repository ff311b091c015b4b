// A user's explicit Runge–Kutta tableau as an Integrator (--integrator tableau:FILE):
//
//   k_i = f(t + c_i Δt, y + Δt Σ_{j<i} a_ij k_j),   y_{n+1} = y_n + Δt Σ_i b_i k_i
//
// The block structure of include/dlpverify/runge_kutta.hpp with the coefficients at run time:
// blocks of 64 members carried through all their steps, one block per OpenMP thread, the stages
// in structure-of-arrays form, one Problem::rhs call per block and stage. The arithmetic is the
// built-in one's, operation for operation (zero coefficients skipped, the stage argument's first
// term fused with the copy of y, the weights added in stage order), so a file with the built-in
// coefficients gives the built-in integrator's bits. The tableau runs as written: its order
// conditions are checked (order_conditions.hpp) but never corrected.
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "dlpverify/butcher_method.hpp"
#include "dlpverify/integrator.hpp"
#include "integrators/registry.hpp"
#include "integrators/tableau/tableau_file.hpp"

namespace dlpverify {

inline constexpr const char* kTableauPrefix = "tableau:";

// The file an integrator spec "tableau:FILE" names, or nullopt for any other spec.
inline std::optional<std::string> tableau_file_of(const std::string& spec) {
  if (spec.rfind(kTableauPrefix, 0) != 0) return std::nullopt;
  return spec.substr(std::string(kTableauPrefix).size());
}

class TableauIntegrator final : public Integrator, public ButcherMethod {
 public:
  static constexpr int kBlock = 64;  // members per block, as ExplicitRungeKutta's

  explicit TableauIntegrator(RuntimeTableau tableau);
  // "tableau:FILE", the name it was asked for by.
  std::string name() const override { return kTableauPrefix + tableau_.source; }
  // The file's claimed order (what a study expects), whether the conditions hold or not.
  int order() const override { return tableau_.order; }
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override;
  // Steps and whole-population right-hand-side evaluations, s per step.
  SolverStatistics statistics() const override { return statistics_; }
  const RuntimeTableau& tableau() const { return tableau_; }
  // ButcherMethod: the file's coefficients, for a study in extended precision.
  ButcherCoefficients butcher() const override { return {tableau_.a, tableau_.b, tableau_.c}; }

 private:
  RuntimeTableau tableau_;
  SolverStatistics statistics_;
};

// The one line that names the conditions the file's claims rely on and miss ("tableau FILE: row
// sum c_2 = 0.6 but Σ_j a_2j = 0.5"), or "" when every one holds.
std::string tableau_warning(const RuntimeTableau& tableau);

// Reads the file (InputError for a malformed one) and makes its integrator: a TableauIntegrator for
// an explicit tableau, an ArkodeDirkIntegrator for a diagonally implicit one (on one rank only:
// InputError under mpirun). When the file misses a condition its claims rely on, the integrator's
// first advance() says so on `warnings` ("dlpverify: warning: " + tableau_warning), once per file
// and process: a study makes its integrator more than once and may then stop at bad input, whose
// one line stays the only one.
std::unique_ptr<Integrator> make_tableau_integrator(const std::string& path, std::ostream& warnings);

// How the integrator of `tableau` steps: an explicit one as the Runge–Kutta methods, each member
// alone; a diagonally implicit one the whole population at once, in ARKStep's vectors (its stages,
// Newton's and GMRES's: counted in a study's memory estimate).
IntegratorTraits tableau_traits(const RuntimeTableau& tableau);

}  // namespace dlpverify
