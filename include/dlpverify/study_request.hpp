/// @file
/// A convergence study as one request to the library: the problem, how to make its integrator,
/// the levels (or a search for them), the reference and what a check expects go in; the result,
/// the verdict with every reason and the report come out (docs/architecture.md, "The study").
///
/// run() conducts the whole study: under mpirun each rank solves its own share of the members
/// (docs/mpi.md), the reference is computed, the levels are solved (continuing from the levels a
/// StudyProgress hands it, and stopping when it asks), the verdict is judged — the fitted orders,
/// the orders extrapolated by a level search, the search's coverage, the error-constant gate
/// against a baseline — and a missed order is explained. Writing the report is the caller's:
/// run() writes no file and prints nothing.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/history.hpp"
#include "dlpverify/integrator.hpp"
#include "dlpverify/level_search.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/recorded_study.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// What a check expects of a study; its verdict fails when any expectation is missed.
struct StudyExpectation {
  double order = 0.0;            ///< the expected order of accuracy P
  double order_tolerance = 0.1;  ///< a variable passes when |fitted order − P| ≤ this
  /// A recorded result of this same study (read_recorded_study_file): each variable's error
  /// constant must stay within constant_tolerance of the baseline's; a baseline of another study
  /// is an InputError naming the "baseline", once the levels are solved.
  std::optional<RecordedStudy> baseline;
  double constant_tolerance = kDefaultConstantTolerance;  ///< the relative band around the baseline's constants
};

/// A convergence study, everything it needs.
struct StudyRequest {
  const Problem* problem = nullptr;  ///< the whole population; under mpirun every rank passes it whole
  MakeIntegrator make_integrator;    ///< called once, for this rank's share of problem
  /// How that integrator steps the population: under mpirun one that steps it whole at once is
  /// refused (InputError naming the "integrator"). Serially any reach runs.
  IntegratorReach reach = IntegratorReach::whole_population;
  StudyPlan plan;                    ///< the levels (with a search: its start), variables, expected order
  ReferenceSettings reference;       ///< what the levels are compared with
  std::optional<LevelSearchRules> search;  ///< find the levels instead of running plan.levels
  std::optional<StudyExpectation> check;   ///< judge the study (none: a convergence study alone)
  /// A check of fixed levels that could not decide goes on by itself (Escalation): to finer levels
  /// while no floor is reached, to extended precision where double's round-off floor or the
  /// reference's accuracy came first and the tool can step the integrator and the problem there;
  /// false: the single pass alone.
  bool escalate = true;
  /// The most seconds the escalation's levels may take: it then ends with the verdict it has.
  double escalation_budget_seconds = 120.0;
  /// The finest level's error over time at this many output times (0: not recorded).
  int history_outputs = 0;
  /// Keep every member's finest state and reference, gathered on rank 0 (the per-member view).
  bool keep_member_states = false;
  nlohmann::json options = nlohmann::json::object();     ///< as the report shows them
  nlohmann::json provenance = nlohmann::json::object();  ///< build, host, date, command line
};

/// What a check that could not decide did next (StudyRequest::escalate): it ran the study again
/// with finer levels, or in extended precision, one level more at a time until the verdict was
/// decided at two level counts in a row, or it says why nothing the tool controls could do so.
struct Escalation {
  /// What an escalated study changes.
  enum class Means {
    extended_precision,  ///< its arithmetic: some undecided variable reached double's round-off floor or the reference's accuracy
    finer_levels,        ///< its levels alone, searched in the same arithmetic: no undecided variable reached a floor
  };
  Means means = Means::extended_precision;  ///< what this escalation changed
  bool ran = false;                      ///< the escalated study ran; its outcome is the one reported
  std::string not_possible;              ///< why not, when it did not run
  /// The first study's findings that could not decide: the escalation's cause
  std::vector<std::string> double_findings;
  int double_levels = 0;                 ///< the levels the first study ran
  int levels = 0;                        ///< the levels the escalated study ended on
  double seconds = 0.0;                  ///< the escalated study's wall time, its reference too
  bool budget_spent = false;             ///< it ended on escalation_budget_seconds, not on a decided verdict
  /// The levels a search of finer levels in double ran before extended precision, when it reached
  /// a floor undecided (0: no such search ran)
  int searched_levels = 0;
  double searched_seconds = 0.0;         ///< that search's wall time, part of `seconds`' budget
};

/// A finished study as rank 0 reports it.
struct StudyOutcome {
  /// False on every rank but rank 0, whose outcome is the study's: the rest is then empty.
  bool reported = false;
  StudyDescription description;         ///< the case, integrator, reference and options
  StudyResult result;                   ///< the levels, norms and orders
  std::optional<LevelSearch> search;    ///< what a level search ran and why it stopped
  std::optional<CheckVerdict> verdict;  ///< with a check: each variable's finding
  std::optional<Escalation> escalation;  ///< when the check could not decide in double
  std::string table;                    ///< the console table, with the search and a missed order's reasons
  nlohmann::json report;                ///< the JSON result, with the same additions
  std::vector<HistoryPoint> history;    ///< the finest level's error over time (history_outputs > 0)
  State reference_state;                ///< the reference, every member's (keep_member_states)
  /// 0 done, 1 the check failed, 5 it could not decide (errors.hpp).
  int exit_code() const { return verdict ? verdict->exit_code() : kExitDone; }
};

/// Runs `request`, continuing and recording through `progress` (StudyProgress: the levels an
/// earlier run finished, each new one handed on, a stop asked before each level; empty: none).
/// Throws StudyStopped when progress asked it to stop, InputError for a request that cannot be
/// run (its quantity named in the API's words), SolverError naming the case when a solve fails.
StudyOutcome run(const StudyRequest& request, const StudyProgress& progress = {});

}  // namespace dlpverify
