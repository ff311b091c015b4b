#include "dlpverify/case_report.hpp"
#include "dlpverify/precision_request.hpp"

#include <utility>

#include "harness/distribution.hpp"
#include "harness/rank_share.hpp"
#include "harness/step_unit.hpp"
#include "study/distributable.hpp"
#include "study/sweep_reference.hpp"

namespace dlpverify {

namespace {

void check_request(const PrecisionRequest& request) {
  if (request.problem == nullptr || !request.make_fixed_step)
    throw InputError("work-precision study", "incomplete", "needs a problem and a fixed-step method");
  for (const AdaptiveMethod& method : request.adaptive)
    if (!method.solve) throw InputError("work-precision study", method.name, "an adaptive method without a solve");
  if (!request.adaptive.empty() && request.rtols.empty())
    throw InputError("work-precision study", "no rtol", "its adaptive methods need a tolerance to run at");
  check_plan(request.plan);
  check_reference_settings(request.reference);
  if (!request.rtols.empty()) check_reference_below(request.reference, request.rtols.back());
  for (const AdaptiveMethod& method : request.adaptive) check_distributable(method.reach, method.name, request.reference);
  check_distributable(request.fixed_step_reach, request.fixed_step, request.reference);
}

// Each adaptive method over the sweep, then the fixed-step method at each level. Every run starts
// from a copy of `initial` with a fresh integrator, so none inherits another's state.
std::vector<PrecisionRun> runs_of(const PrecisionRequest& request, const Problem& problem, const State& initial) {
  const double t_end = request.plan.t_end;
  const double t0 = problem.initial_time();
  std::vector<PrecisionRun> runs;
  for (const AdaptiveMethod& method : request.adaptive)
    for (const double rtol : request.rtols)
      runs.push_back({method.name, rtol, std::nullopt, [&method, &problem, &initial, t0, t_end, rtol](SolverStatistics& statistics) {
                        State state = initial;
                        method.solve(problem, state, t0, t_end, rtol, statistics);
                        return problem.measured(state, t_end);
                      }});
  for (const long steps : level_steps(request.plan)) {
    const double dt = t_end / static_cast<double>(steps);  // lands on t_end whatever the ratio
    runs.push_back({request.fixed_step, std::nullopt, dt,
                    [&request, &problem, &initial, t0, t_end, dt, steps](SolverStatistics& statistics) {
                      const std::unique_ptr<Integrator> integrator = request.make_fixed_step(problem);
                      State state = initial;
                      integrator->advance(problem, state, t0, dt, steps);
                      statistics = integrator->statistics();
                      return problem.measured(state, t_end);
                    }});
  }
  return runs;
}

WorkPrecisionDescription describe(const PrecisionRequest& request, const Reference& reference) {
  const Problem& whole = *request.problem;
  WorkPrecisionDescription description;
  description.case_name = whole.name();
  description.reference = reference.kind;
  description.reference_detail = reference.detail;
  description.reference_statistics = reference.statistics;
  description.particles = whole.members();
  description.member_nouns = member_nouns(whole);
  description.t0 = whole.initial_time();
  description.t_end = request.plan.t_end;
  description.time_unit = step_unit(whole);
  description.options = request.options;
  description.provenance = request.provenance;
  return description;
}

}  // namespace

std::vector<std::string> run_labels(const PrecisionRequest& request) {
  std::vector<std::string> labels;
  for (const AdaptiveMethod& method : request.adaptive)
    for (const double rtol : request.rtols) labels.push_back(run_label(method.name, rtol, std::nullopt));
  for (const long steps : level_steps(request.plan))
    labels.push_back(run_label(request.fixed_step, std::nullopt, request.plan.t_end / static_cast<double>(steps)));
  return labels;
}

PrecisionOutcome run(const PrecisionRequest& given, const Progress<PrecisionRunResult>& progress) {
  check_request(given);
  PrecisionRequest request = given;
  if (request.plan.variables.empty()) request.plan.variables = request.problem->variables();  // as a study's
  // Under mpirun each rank solves its own members (docs/mpi.md); the whole problem is what the
  // report describes.
  const RankShare share(*request.problem);
  const Problem& problem = share.problem();
  const State initial = problem.initial_state();
  const std::vector<PrecisionRun> runs = runs_of(request, problem, initial);

  PrecisionOutcome outcome;
  Reference reference;
  try {
    // Recomputed on every run, a resumed one too: a closed form or CVODE is deterministic.
    reference = compute_reference(problem, request.reference, initial, request.plan.t_end, request.plan.variables);
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": reference: " + e.what());
  }
  try {
    outcome.result = run_work_precision(runs, problem.measured(reference.state, request.plan.t_end),
                                        reference.error_estimate, request.plan.variables, progress);
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": " + e.what());
  }
  if (progress.stop && progress.stop()) throw StudyStopped(static_cast<int>(runs.size()));
  if (distribution().rank() != 0) return outcome;  // rank 0 reports (src/mpi/session.hpp)

  outcome.reported = true;
  outcome.description = describe(request, reference);
  outcome.table = format_table(outcome.description, outcome.result);
  outcome.report = to_json(outcome.description, outcome.result);
  return outcome;
}

}  // namespace dlpverify
