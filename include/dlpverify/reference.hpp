/// @file
/// The reference a study measures every level against, computed once per study (never per level):
/// the problem's closed form, or CVODE at a tight tolerance where there is none (docs/model.md §4).
///
/// A CVODE reference carries an estimate of its own error: a second solve at rtol/10, compared
/// with the first, variable by variable (L2 over the population). The harness then refuses to
/// trust a study whose finest level is not at least 100× more wrong than the reference.
///
/// Members are independent, so CVODE solves blocks of kReferenceBlock members, each with its own
/// solver, one per thread: a block's vectors stay in cache, where a whole-population vector
/// streams from memory (CVODE's Adams predictor sweeps its ~q²/2 Nordsieck vectors every step; on
/// the seed sphere, 268 MB per vector, that took 1.7 s a step). Each block gets its own error
/// control, at least as tight as one over the whole population, with absolute tolerances scaled
/// by the whole population's field sizes so every block is held to the same standard.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/integrator.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// Where the reference comes from.
enum class ReferenceKind {
  exact,  ///< the problem's closed form
  cvode   ///< CVODE Adams at a tight tolerance, with an estimate of its own error
};

/// How the reference is computed.
struct ReferenceSettings {
  ReferenceKind kind = ReferenceKind::exact;  ///< closed form or CVODE
  double rtol = 1e-12;       ///< CVODE reference; absolute tolerances scale per field
  long max_steps = 100000;   ///< per solve
  /// Restart CVODE at each member's kink (Problem::kink_times), where the solution is only once
  /// differentiable: the audit of closed forms does; a study reference does not (yet).
  bool restart_at_kinks = false;
};

/// The reference state at t0 + t_end and what is known of its accuracy.
struct Reference {
  State state;                         ///< at t0 + t_end (the fields; Problem::measured gives the measured columns)
  std::string kind;                    ///< "exact" | "cvode"
  std::string detail;                  ///< which closed form, or CVODE's settings
  std::vector<double> error_estimate;  ///< per measured variable; 0 for a closed form (round-off only)
  nlohmann::json statistics = nlohmann::json::object();  ///< solver counts and wall time
};

/// Throws InputError naming the reference when the problem has no closed form and exact was asked for.
Reference compute_reference(const Problem& problem, const ReferenceSettings& settings, const State& initial,
                            double t_end, const std::vector<Variable>& variables);

/// CVODE Adams from t0 + tau_from over `duration`, in blocks of members (the banner), no step
/// longer than `duration`. Fills solver counts into `statistics`.
State solve_with_cvode(const Problem& problem, const State& from, double tau_from, double duration,
                       const ReferenceSettings& settings, nlohmann::json& statistics, const State* scale_from = nullptr);

/// The reference at increasing times τ (for error histories): the closed form from the initial
/// state, or CVODE continued from the previous time with the settings of compute_reference.
std::function<State(double tau)> reference_trajectory(const Problem& problem, const ReferenceSettings& settings,
                                                      const State& initial);

/// The study of `integrator` on `problem` against a reference of `settings` (the closed form, or
/// CVODE with its error estimate and the trust margin). Empty plan.variables: the problem's own.
StudyResult run_study(const Problem& problem, Integrator& integrator, StudyPlan plan, const ReferenceSettings& settings);

}  // namespace dlpverify
