/// @file
/// A work-precision study as one request to the library (dlpverify/work_precision.hpp): adaptive
/// methods swept over tolerances and a fixed-step method at levels, each run from the initial
/// state against the reference; the runs' errors and work, the table and the report come out.
/// Under mpirun each rank solves its own share of the members (docs/mpi.md). run() writes no file
/// and prints nothing.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/integrator.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/tolerance_study.hpp"
#include "dlpverify/work_precision.hpp"

namespace dlpverify {

/// An adaptive method of the sweep, by the name its runs carry ("adams", "bdf").
struct AdaptiveMethod {
  std::string name;       ///< as the runs and the report name it
  SolveAtTolerance solve;  ///< the method at one rtol, called once per run
  /// How it steps the population: under mpirun one that steps it whole at once is refused.
  IntegratorReach reach = IntegratorReach::whole_population;
};

/// A work-precision study, everything it needs.
struct PrecisionRequest {
  const Problem* problem = nullptr;     ///< the whole population; under mpirun every rank passes it whole
  std::vector<AdaptiveMethod> adaptive;  ///< each run at every rtol, in this order, before the fixed-step runs
  std::vector<double> rtols;            ///< loosest first (tolerance_sweep)
  std::string fixed_step;               ///< the fixed-step method's name
  MakeIntegrator make_fixed_step;       ///< made afresh for every level, for this rank's share
  /// How it steps the population: under mpirun one that steps it whole at once is refused.
  IntegratorReach fixed_step_reach = IntegratorReach::whole_population;
  StudyPlan plan;                       ///< the fixed-step levels, the duration and the variables (empty: the problem's)
  /// What the runs are compared with. A CVODE reference must be at least a decade tighter than the
  /// tightest rtol: else InputError naming the "reference relative tolerance".
  ReferenceSettings reference;
  nlohmann::json options = nlohmann::json::object();     ///< as the report shows them
  nlohmann::json provenance = nlohmann::json::object();  ///< build, host, date, command line
};

/// A finished study as rank 0 reports it.
struct PrecisionOutcome {
  /// False on every rank but rank 0, whose outcome is the study's: the rest is then empty.
  bool reported = false;
  WorkPrecisionDescription description;  ///< the case, reference and options (format_csv takes it)
  WorkPrecisionResult result;            ///< every run's error and work
  std::string table;                     ///< the console table
  nlohmann::json report;                 ///< the JSON result
};

/// The runs `request` makes, in order, by their labels (run_label): what a journal of the study
/// records as its identity.
std::vector<std::string> run_labels(const PrecisionRequest& request);

/// Runs `request`, continuing and recording through `progress` (the runs an earlier run of the
/// same study finished, each new one handed on, a stop asked before each run; empty: none).
/// Throws StudyStopped when progress asked it to stop, InputError for a request that cannot be
/// run, SolverError naming the case (and the run, or the reference) when a solve fails.
PrecisionOutcome run(const PrecisionRequest& request, const Progress<PrecisionRunResult>& progress = {});

}  // namespace dlpverify
