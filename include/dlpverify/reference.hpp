/// @file
/// The reference a study measures every level against, computed once per study (never per level):
/// the problem's closed form; CVODE at a tight tolerance; any integrator at a fixed step; or the
/// closed form ŷ of a manufactured problem (docs/verification.md, "The reference").
///
/// Every reference but a closed form carries an estimate of its own error, variable by variable
/// (L2 over the population, of the measured columns): CVODE's is a second solve at rtol/10
/// compared with the first; a fixed-step integrator's is a second solve at Δt/2, the difference
/// scaled by 2^p/(2^p − 1) for an integrator of order p (Richardson). The harness then refuses to
/// trust a study whose finest level is not at least 100× more wrong than the reference
/// (kMinimumReferenceMargin).
///
/// Members are independent, so CVODE solves blocks of kReferenceBlock members, each with its own
/// solver, one per thread: a block's vectors stay in cache, where a whole-population vector
/// streams from memory (CVODE's Adams predictor sweeps its ~q²/2 Nordsieck vectors every step; on
/// the seed sphere, 268 MB per vector, that took 1.7 s a step). Each block gets its own error
/// control, at least as tight as one over the whole population, with absolute tolerances scaled
/// by the whole population's field sizes so every block is held to the same standard.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/integrator.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

class ExtendedState;

/// Where the reference comes from.
enum class ReferenceKind {
  exact,       ///< the problem's closed form
  cvode,       ///< CVODE Adams at a tight tolerance, with an estimate of its own error
  integrator,  ///< any integrator at a fixed step Δt, its error estimated against Δt/2
  /// the closed form ŷ of a manufactured problem: the problem handed to the study is the
  /// manufactured one, y′ = f(t, y) + ŷ′(t) − f(t, ŷ(t)), whose closed form is ŷ
  manufactured,
  /// the problem's ODE solved in Extended (double-double) by Gragg–Bulirsch–Stoer extrapolation
  /// to ε_Extended, for a problem that offers ExtendedRhs (dlpverify/extended.hpp): tighter than
  /// any CVODE reference, for a study in double as for one in extended precision
  extended
};

/// Richardson's factor for the error of a fixed-step solution y_dt estimated against y_{dt/2}:
/// ‖y_dt − y‖ ≈ ‖y_dt − y_{dt/2}‖ · 2^p / (2^p − 1) for a method of order p; an unknown order
/// (p = 0) gets 2, the factor of p = 1 and the largest of every p ≥ 1. Used by the integrator
/// reference and by `dlpverify analyze --reference-check` (halved_step_error).
double halved_step_error_factor(int order);

/// The estimated error per variable of a fixed-step solution from its solution at half the step
/// (both measured columns): ‖y_dt − y_{dt/2}‖ (L2 over the population) × halved_step_error_factor(order).
std::vector<double> halved_step_error(const State& solution, const State& halved, const std::vector<Variable>& variables,
                                      int order);

/// "exact", "cvode", "integrator", "manufactured" or "extended", as reports and journals name the kind.
const char* reference_kind_name(ReferenceKind kind);

/// The tightest relative tolerance a CVODE reference is solved at: its error estimate (rtol/10)
/// then sits at 1e-15, a few units of double rounding; tighter, CVODE only measures rounding.
inline constexpr double kTightestReferenceRtol = 1e-14;

/// The most steps a CVODE solve may be allowed (CVodeSetMaxNumSteps), reference or integrator.
inline constexpr long kMostCvodeSteps = 1000000000;

/// How the reference is computed.
struct ReferenceSettings {
  ReferenceKind kind = ReferenceKind::exact;  ///< which reference
  double rtol = 1e-12;       ///< CVODE reference; absolute tolerances scale per field
  long max_steps = 100000;   ///< per solve
  /// Restart CVODE at each member's kink (Problem::kink_times), where the solution is only once
  /// differentiable: the audit of closed forms does; a study reference does not (yet).
  bool restart_at_kinks = false;
  /// Integrator reference: the method, shared so that settings stay a value (it may be the
  /// integrator under test: the reference is solved before the levels)…
  std::shared_ptr<Integrator> integrator;
  /// … and its fixed step; t_end / dt must be a whole number of steps (the rule of level_steps).
  double dt = 0.0;
  /// How the integrator reference steps the population: under mpirun it must step each member
  /// alone (the others take norms over the whole population inside their steps).
  IntegratorReach integrator_reach = IntegratorReach::whole_population;
};

/// The reference state at t0 + t_end and what is known of its accuracy.
struct Reference {
  State state;                         ///< at t0 + t_end (the fields; Problem::measured gives the measured columns)
  std::string kind;                    ///< reference_kind_name of the settings' kind
  std::string detail;                  ///< which closed form, or CVODE's settings
  std::vector<double> error_estimate;  ///< per measured variable; 0 for a closed form (round-off only)
  nlohmann::json statistics = nlohmann::json::object();  ///< solver counts and wall time
  /// An extended reference's state in Extended, whose nearest doubles `state` holds (a study in
  /// extended precision measures against it); null for every other kind.
  std::shared_ptr<const ExtendedState> extended;
};

/// The settings of the next tighter reference, for a study whose levels came within
/// kMinimumReferenceMargin of it: CVODE at rtol/100 (not below kTightestReferenceRtol), an
/// integrator at Δt/ratio (a whole ratio keeps t_end/Δt whole); nullopt for a closed form, a
/// manufactured reference, CVODE already at its floor or a ratio that is not whole.
std::optional<ReferenceSettings> tightened_reference(const ReferenceSettings& settings, double ratio);

/// Refuses settings no reference can be computed with, whatever its kind, before any work: a
/// "reference relative tolerance" outside [kTightestReferenceRtol, 1e-3) (a reference must be
/// tighter than what it measures) and a "CVODE step limit" outside [1, kMostCvodeSteps]. Throws
/// InputError naming the quantity.
void check_reference_settings(const ReferenceSettings& settings);

/// The reference at t0 + t_end from `initial`, with its error estimate per variable of `variables`
/// (computed on Problem::measured of the two solves). Throws InputError naming the reference when
/// the problem has no closed form and exact (or manufactured) was asked for, when an integrator
/// reference has no integrator, or its dt is not a whole fraction of t_end.
Reference compute_reference(const Problem& problem, const ReferenceSettings& settings, const State& initial,
                            double t_end, const std::vector<Variable>& variables);

/// CVODE Adams from t0 + tau_from over `duration`, in blocks of members (the banner), no step
/// longer than `duration`. Fills solver counts into `statistics`.
State solve_with_cvode(const Problem& problem, const State& from, double tau_from, double duration,
                       const ReferenceSettings& settings, nlohmann::json& statistics, const State* scale_from = nullptr);

/// The reference at increasing times τ (for error histories): the closed form from the initial
/// state, or CVODE continued from the previous time with the settings of compute_reference, or
/// the integrator continued from the previous time in ⌈Δτ/dt⌉ equal steps (none longer than dt).
std::function<State(double tau)> reference_trajectory(const Problem& problem, const ReferenceSettings& settings,
                                                      const State& initial);

}  // namespace dlpverify
