/// @file
/// An adaptive integrator verified by its tolerance (docs/verification.md, "Adaptive integrators
/// by tolerance"): one run per relative tolerance rtol over the study's duration, each measured
/// against the reference like a level. Per variable, the relative L2 error e_i of each run, the
/// exponent E of e ≈ C rtol^E fitted by least squares over the runs the reference can judge (the
/// order fit of order.hpp, with rtol in place of Δt, and its Student-t 95% interval), whether the
/// error falls at every tightening, and e_i / rtol_i. A code whose error is proportional to its
/// tolerance has E = 1; one that ignores its tolerance has E ≈ 0.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "dlpverify/norms.hpp"
#include "dlpverify/order.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/solver_statistics.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// An adaptive integrator at a relative tolerance: advances `state` of `problem` (a rank's share
/// under mpirun) from t0 to t0 + duration choosing its own steps to `rtol`, and fills the solver's
/// counts. Every call starts afresh: no run inherits another's state.
using SolveAtTolerance = std::function<void(const Problem& problem, State& state, double t0, double duration, double rtol,
                                            SolverStatistics& statistics)>;

/// One run of the sweep: the state at t0 + t_end at tolerance `rtol`, with the solver's counts.
struct ToleranceRun {
  double rtol = 0.0;  ///< the relative tolerance asked for
  /// Returns the measured state at t0 + t_end and fills the solver's statistics.
  std::function<State(SolverStatistics& statistics)> solve;
};

/// What one run reached and spent.
struct ToleranceRunResult {
  double rtol = 0.0;                    ///< as asked
  std::vector<ErrorNorms> norms;        ///< one per variable
  std::vector<double> reference_margin; ///< L2 error / the reference's error (infinite: a closed form)
  SolverStatistics solver_statistics;   ///< steps, rhs evaluations, rejected steps where reported
};

/// Per variable, how the error follows the tolerance.
struct Proportionality {
  OrderFit exponent;                  ///< slope of ln e against ln rtol over `exponent.levels` (run indices)
  bool falls_steadily = true;         ///< e_{i+1} < e_i at every tightening of the fitted runs
  std::vector<double> error_over_tolerance;  ///< e_i / rtol_i per run (e_i relative L2)
};

/// A finished tolerance study.
struct ToleranceStudy {
  std::vector<Variable> variables;          ///< measured, in norm order
  std::vector<double> reference_error;      ///< per variable; 0 for a closed form
  std::vector<ToleranceRunResult> runs;     ///< loosest first
  std::vector<Proportionality> proportionality;  ///< per variable
};

/// Runs every run in order against `reference` and fits each variable's exponent over the runs
/// whose error is finite, positive and at least kMinimumReferenceMargin × the reference's.
/// Unlike run_work_precision it takes a run that reports no counts (an exec: program).
ToleranceStudy run_tolerance_study(const std::vector<ToleranceRun>& runs, const State& reference,
                                   const std::vector<double>& reference_error, const std::vector<Variable>& variables);

/// The verdict: each variable passes when at least three runs were fitted and
/// |E − expected| ≤ tolerance; an exponent within 0.25 of 0 fails as an integrator that ignores
/// its tolerance. An error that does not fall at every tightening is said, not failed: error
/// control keeps the local error, not the global one, below the tolerance, and CVODE's global
/// error wanders by a factor of a few about the trend. Outcomes as check_orders':
/// order_within, order_miss, no_order.
CheckVerdict check_proportionality(const ToleranceStudy& study, double expected, double tolerance);

/// The console table: per run rtol, steps, rhs evaluations, rejected steps (and, when a run
/// solved implicit stages, Newton iterations and failures, Krylov iterations and failures), then
/// the relative error and e/rtol per variable; the fitted exponents with their intervals; the verdict.
std::string format_tolerance_table(const std::string& header, const ToleranceStudy& study,
                                   const std::optional<CheckVerdict>& verdict);
/// {"runs": [{rtol, steps, rhs_evals, rejected_steps, nonlinear_iterations,
///  nonlinear_convergence_failures, linear_iterations, linear_convergence_failures,
///  rhs_evals_jacobian (null where not counted), relative_VAR, l2_VAR, error_over_tolerance_VAR}…],
///  "proportionality": {VAR: {exponent, stderr, ci95, runs_used, falls_steadily}}, "check": …}.
nlohmann::json to_json(const ToleranceStudy& study, const std::optional<CheckVerdict>& verdict);

}  // namespace dlpverify
