/// @file
/// A study of an adaptive integrator by its tolerance as one request to the library
/// (docs/verification.md, "Adaptive integrators by tolerance"): the problem, the integrator at any
/// rtol, the sweep of tolerances, the reference and the exponent a check expects go in; the sweep,
/// the verdict and the report come out. Under mpirun each rank solves its own share of the members
/// (docs/mpi.md). run() writes no file and prints nothing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/tolerance_study.hpp"

namespace dlpverify {

/// What a check expects of the sweep: the error proportional to rtol^exponent.
struct ProportionalityExpectation {
  double exponent = 1.0;    ///< E of e ≈ C rtol^E
  double tolerance = 0.25;  ///< a variable passes when |fitted E − exponent| ≤ this
};

/// A sweep of tolerances, everything it needs.
struct ToleranceRequest {
  const Problem* problem = nullptr;   ///< the whole population; under mpirun every rank passes it whole
  std::string integrator;             ///< its name, as the report shows it
  SolveAtTolerance solve;             ///< the integrator at one rtol, called once per run
  /// How it steps the population: under mpirun one that steps it whole at once is refused.
  IntegratorReach reach = IntegratorReach::whole_population;
  std::vector<double> rtols;          ///< loosest first (tolerance_sweep)
  double t_end = 0.0;                 ///< the duration of every run, after the problem's initial time
  std::vector<Variable> variables;    ///< measured, in norm order (empty: the problem's)
  /// What the runs are compared with. A CVODE reference must be at least a decade tighter than the
  /// tightest rtol, or the tightest runs measure the reference against itself: else InputError
  /// naming the "reference relative tolerance".
  ReferenceSettings reference;
  std::optional<ProportionalityExpectation> check;        ///< judge the sweep (none: a study alone)
  nlohmann::json options = nlohmann::json::object();     ///< as the report shows them
  nlohmann::json provenance = nlohmann::json::object();  ///< build, host, date, command line
};

/// A finished sweep as rank 0 reports it.
struct ToleranceOutcome {
  /// False on every rank but rank 0, whose outcome is the sweep's: the rest is then empty.
  bool reported = false;
  ToleranceStudy study;                 ///< the runs, their errors and the fitted exponents
  std::optional<CheckVerdict> verdict;  ///< with a check: each variable's finding
  std::string table;                    ///< the console table under its header
  nlohmann::json report;                ///< the JSON result, with the case, reference and options
  /// 0 done, 1 the check failed, 5 it could not decide (errors.hpp).
  int exit_code() const { return verdict ? verdict->exit_code() : kExitDone; }
};

/// Runs `request`: the reference, then one run per rtol from the initial state. Throws InputError
/// for a request that cannot be run, SolverError naming the case when a solve fails.
ToleranceOutcome run(const ToleranceRequest& request);

}  // namespace dlpverify
