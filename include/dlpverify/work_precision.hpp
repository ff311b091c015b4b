/// @file
/// The work-precision study: for each run of some method (a CVODE tolerance, a fixed step), the
/// accuracy it reaches (docs/model.md §5 norms against the reference) and the work it spends for it (RHS
/// evaluations, steps, wall time). Plotting error against work puts methods of different kinds
/// on one axis: where a variable-order method overtakes a fixed-step one, and at what accuracy.
///
/// Like the convergence study, the loop knows neither the physics nor the integrators: each run
/// is a function returning the state at t0 + t_end and filling the solver's statistics, which
/// must report steps and rhs_evals (the fixed-step integrators, ARKODE and CVODE all do).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/case_report.hpp"
#include "dlpverify/norms.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// One run of a work-precision study: an adaptive method at rtol or a fixed-step one at dt.
struct PrecisionRun {
  std::string method;          ///< adams | bdf | rk2 | …
  std::optional<double> rtol;  ///< the tolerance of an adaptive run
  std::optional<double> dt;    ///< the step of a fixed-step run
  /// Returns the state at t0 + t_end and fills the solver's statistics.
  std::function<State(SolverStatistics& statistics)> solve;
};

/// What one run reached and spent.
struct PrecisionRunResult {
  std::string method;          ///< as in PrecisionRun
  std::optional<double> rtol;  ///< as in PrecisionRun
  std::optional<double> dt;    ///< as in PrecisionRun
  long steps = 0;              ///< the solver's SolverStatistics::steps
  /// Every evaluation of the right-hand side: rhs_evals plus the rhs_evals_jacobian a solver
  /// counts apart (BDF's CVDiag difference quotient, SPGMR's Jacobian-vector products), since
  /// each costs as much as any other.
  long rhs_evals = 0;
  double wall_seconds = 0.0;               ///< the solve alone, steady clock
  std::vector<ErrorNorms> norms;           ///< one per measured variable
  std::vector<double> reference_margin;    ///< error / the reference's own error (infinite: closed form)
  bool reference_limited = false;          ///< some margin < kMinimumReferenceMargin (study.hpp)
  SolverStatistics solver_statistics;  ///< as the run's solve filled them
};

/// A finished work-precision study.
struct WorkPrecisionResult {
  std::vector<Variable> variables;       ///< the measured variables, in norm order
  std::vector<double> reference_error;  ///< per variable; 0 for a closed form
  std::vector<PrecisionRunResult> runs;  ///< in the order given
};

/// Runs every run once, in order, timing each and measuring its state against `reference`.
/// reference_error: the reference's estimated error per variable (zeros, or empty, for a closed
/// form). A SolverError from a run propagates, prefixed with the run ("bdf at rtol 1e-05: …").
/// progress.done: the first runs as an earlier run of the same sweep finished them (method, rtol
/// and dt must match, or InputError); their reference margins are judged again.
WorkPrecisionResult run_work_precision(const std::vector<PrecisionRun>& runs, const State& reference,
                                       const std::vector<double>& reference_error,
                                       const std::vector<Variable>& variables,
                                       const Progress<PrecisionRunResult>& progress = {});

/// rtol_max, rtol_max / 10^(1/per_decade), … down to the last point at or above rtol_min (within
/// 1e-9 relative), each rounded to 12 significant digits so 1e-3 … 1e-12 read as written.
std::vector<double> tolerance_sweep(double rtol_max, double rtol_min, int per_decade);

/// "adams at rtol 1e-05", "rk2 at dt 0.000125": a run's name in messages.
std::string run_label(const std::string& method, const std::optional<double>& rtol, const std::optional<double>& dt);

/// What was studied, for the report's header.
struct WorkPrecisionDescription {
  std::string case_name;         ///< the problem's name()
  std::string reference;         ///< "exact" or "cvode"
  std::string reference_detail;  ///< which closed form, or the reference solver's settings
  nlohmann::json reference_statistics = nlohmann::json::object();  ///< the reference solve's counts
  long long particles = 0;                                        ///< members N
  MemberNouns member_nouns;  ///< what the members are called: the problem's MemberNoun
  double t0 = 0.0;                                                ///< start time, in time_unit
  double t_end = 0.0;                                    ///< duration after t0
  std::string time_unit = "s";  ///< of t0, t_end and dt: the problem's step_unit ("1": dimensionless)
  nlohmann::json options = nlohmann::json::object();     ///< every option with its value
  nlohmann::json provenance = nlohmann::json::object();  ///< build, host, date, command line
};

/// Console table: method, rtol or dt, steps, RHS evals, wall s, then L2 and relative L2 per variable.
std::string format_table(const WorkPrecisionDescription& description, const WorkPrecisionResult& result);
/// One row per run, with a `# dlpverify …` provenance header.
std::string format_csv(const WorkPrecisionDescription& description, const WorkPrecisionResult& result);
/// case, reference, reference_detail, particles, t0, t_end, time_unit, variables (names, in order),
/// units (name → unit), runs (method, rtol or dt, rhs_evals, steps,
/// wall_s, l2_<variable>, rel_l2_<variable> for every measured variable, …), options, provenance.
nlohmann::json to_json(const WorkPrecisionDescription& description, const WorkPrecisionResult& result);

}  // namespace dlpverify
