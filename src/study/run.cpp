#include "dlpverify/study_request.hpp"

#include "dlpverify/case_report.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/extended_study.hpp"
#include "dlpverify/missed_order.hpp"
#include "dlpverify/reference_study.hpp"
#include "harness/distribution.hpp"
#include "harness/rank_share.hpp"
#include "harness/step_unit.hpp"
#include "study/distributable.hpp"
#include "study/escalation.hpp"
#include "study/escalation_report.hpp"
#include "study/verdict.hpp"

namespace dlpverify {

namespace {

// The levels of a level search under `rules`, asked to stop by `stop` between levels, and ended by
// the check's verdict (`check`, when the study is judged) once it fails at two levels in a row.
LevelRunner level_search(const LevelSearchRules& rules, const std::function<bool()>& stop,
                         const std::optional<StudyExpectation>& check, LevelSearch& search) {
  FailsCheck fails;
  if (check)
    fails = [order = check->order, tolerance = check->order_tolerance](const StudyResult& study) {
      return check_orders(study, order, tolerance).worst() == FindingResult::fail;
    };
  return [rules, stop, fails, &search](const StudyPlan& plan, const State& reference,
                                       const std::vector<double>& reference_error, const Solve& solve,
                                       const TightenReference& tighten) {
    return search_levels(plan, reference, reference_error, solve, rules, search, stop, tighten, fails);
  };
}

// The finest level's error at `outputs` times from t0 to t0 + t_end: the finest level run again,
// beside the reference's trajectory.
std::vector<HistoryPoint> finest_history(const Problem& problem, Integrator& integrator, const StudyResult& study,
                                         const ReferenceSettings& settings, int outputs) {
  const double t0 = problem.initial_time();
  const LevelResult& finest = study.levels.back();
  const AdvanceSteps advance = [&](State& state, double tau_from, double dt, long steps) {
    integrator.advance(problem, state, t0 + tau_from, dt, steps);
  };
  const Measure measure = [&problem](const State& state, double tau) { return problem.measured(state, tau); };
  const State initial = problem.initial_state();
  return record_history(initial, study.plan.variables, finest.dt, finest.steps, outputs, advance,
                        reference_trajectory(problem, settings, initial), measure);
}

StudyDescription describe_study(const StudyRequest& request, const Integrator& integrator, const Reference& reference,
                                nlohmann::json diagnostics) {
  const Problem& whole = *request.problem;
  StudyDescription description;
  description.case_name = whole.name();
  description.integrator = integrator.name();
  description.integrator_order = integrator.order();
  description.reference = reference.kind;
  description.reference_detail = reference.detail;
  description.reference_statistics = reference.statistics;
  description.particles = whole.members();
  description.member_nouns = member_nouns(whole);
  description.t0 = whole.initial_time();
  description.time_unit = step_unit(whole);
  description.options = request.options;
  description.provenance = request.provenance;
  description.parameters = case_parameters(whole);
  description.diagnostics = std::move(diagnostics);
  return description;
}

// What no study can run, refused before any work.
void check_request(const StudyRequest& request) {
  if (request.problem == nullptr || !request.make_integrator)
    throw InputError("study", "incomplete", "needs a problem and a way to make its integrator");
  check_plan(request.plan, request.search ? 1 : 2);  // a search starts from one level
  check_reference_settings(request.reference);
  if (request.search) check_search_rules(*request.search);
  if (request.search && request.plan.precision == Precision::extended)
    throw InputError("precision", "extended", "runs fixed levels: a level search runs in double");
}

// The study solved, described and judged; its report is run()'s.
JudgedStudy judged_study(const StudyRequest& request, const StudyProgress& progress) {
  // Under mpirun each rank solves its own members only (docs/mpi.md); the whole problem is the
  // one the report describes.
  const RankShare share(*request.problem);
  const Problem& problem = share.problem();
  const std::unique_ptr<Integrator> integrator = request.make_integrator(problem);
  check_distributable(request.reach, integrator->name(), request.reference);
  const auto stop_requested = [&progress] { return progress.stop && progress.stop(); };

  StudyOutcome outcome;
  Reference reference;  // its state: the measured columns the levels are compared with
  try {
    // The reference is recomputed on every run, a resumed one too: every kind is deterministic.
    if (request.search) {
      outcome.search.emplace();
      outcome.result = run_study_with(problem, *integrator, request.plan, request.reference,
                                      level_search(*request.search, progress.stop, request.check, *outcome.search), &reference);
    } else {
      outcome.result = run_study(problem, *integrator, request.plan, request.reference, progress, &reference);
    }
    if (stop_requested()) throw StudyStopped(request.plan.levels);
    if (request.history_outputs > 0)
      outcome.history = finest_history(problem, *integrator, outcome.result, request.reference, request.history_outputs);
    if (stop_requested()) throw StudyStopped(request.plan.levels);
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": " + e.what());
  }

  // Rank 0 reports for every rank. The diagnostics are reduced from every rank's own members; only
  // the per-member view needs every member's finest state and reference on rank 0 (docs/mpi.md).
  StudyResult& study = outcome.result;
  nlohmann::json diagnostics = case_diagnostics(problem, problem.initial_state(), study.finest, request.plan.t_end);
  if (request.keep_member_states) {
    study.finest = distribution().gathered_on_root(study.finest);
    reference.state = distribution().gathered_on_root(reference.state);
  }
  JudgedStudy judged;
  judged.extended_refusal = escalation_refusal(problem, *integrator);
  if (distribution().rank() != 0) {
    judged.outcome = std::move(outcome);
    return judged;
  }

  outcome.reported = true;
  outcome.description = describe_study(request, *integrator, reference, std::move(diagnostics));
  const LevelSearch* search = outcome.search ? &*outcome.search : nullptr;
  if (const std::optional<StudyExpectation>& check = request.check)
    outcome.verdict = judge_study(outcome.description, study, check->order, check->order_tolerance, search,
                                  check->baseline ? &*check->baseline : nullptr, check->constant_tolerance);
  if (request.keep_member_states) outcome.reference_state = std::move(reference.state);
  judged.outcome = std::move(outcome);
  return judged;
}

// The console table and the JSON result of a reported outcome (rank 0's).
void write_report(const StudyRequest& request, StudyOutcome& outcome) {
  const LevelSearch* search = outcome.search ? &*outcome.search : nullptr;
  std::optional<MissContext> context;
  if (outcome.verdict && !outcome.verdict->passed()) context = miss_context(*request.problem, request.plan.t_end);
  StudyReport report = study_report(outcome.description, outcome.result, outcome.verdict, search, context);
  if (outcome.escalation) {
    report.table = format_escalation(*outcome.escalation, outcome.result) + "\n" + report.table;
    report.result["escalation"] = to_json(*outcome.escalation, outcome.result);
  }
  outcome.table = std::move(report.table);
  outcome.report = std::move(report.result);
}

}  // namespace

StudyOutcome run(const StudyRequest& request, const StudyProgress& progress) {
  check_request(request);
  StudyOutcome outcome = escalate(request, judged_study(request, progress), judged_study, progress.stop);
  if (outcome.reported) write_report(request, outcome);
  return outcome;
}

}  // namespace dlpverify
