#include "dlpverify/case_report.hpp"
#include "dlpverify/tolerance_request.hpp"

#include <cmath>
#include <utility>

#include "harness/distribution.hpp"
#include "harness/rank_share.hpp"
#include "io/format.hpp"
#include "study/distributable.hpp"
#include "study/sweep_reference.hpp"

namespace dlpverify {

namespace {

void check_request(const ToleranceRequest& request) {
  if (request.problem == nullptr || !request.solve)
    throw InputError("tolerance study", "incomplete", "needs a problem and an integrator at tolerance");
  if (request.rtols.empty()) throw InputError("tolerance study", "no rtol", "needs at least one tolerance to run at");
  if (!std::isfinite(request.t_end) || request.t_end <= 0.0)
    throw InputError("duration", value_text(request.t_end), "must be positive and finite");
  check_reference_settings(request.reference);
  check_reference_below(request.reference, request.rtols.back());
  check_distributable(request.reach, request.integrator, request.reference);
}

// One run per rtol from a fresh integrator and the initial state, over the whole duration.
std::vector<ToleranceRun> runs_of(const ToleranceRequest& request, const Problem& problem, const State& initial) {
  std::vector<ToleranceRun> runs;
  for (const double rtol : request.rtols)
    runs.push_back({rtol, [&request, &problem, &initial, rtol](SolverStatistics& statistics) {
                      State state = initial;
                      request.solve(problem, state, problem.initial_time(), request.t_end, rtol, statistics);
                      return problem.measured(std::move(state), request.t_end);
                    }});
  return runs;
}

nlohmann::json report_of(const ToleranceRequest& request, const ToleranceOutcome& outcome, const Reference& reference) {
  nlohmann::json json = to_json(outcome.study, outcome.verdict);
  json["variables"] = nlohmann::json::array();
  for (const Variable& v : request.variables) json["variables"].push_back(v.name);
  const Problem& whole = *request.problem;
  json.update({{"case", whole.name()}, {"integrator", request.integrator}, {"reference", reference.kind},
               {"reference_detail", reference.detail}, {"particles", whole.members()},
               {"member_noun", whole.members() == 1 ? member_nouns(whole).one : member_nouns(whole).many}, {"t_end", request.t_end},
               {"options", request.options}, {"provenance", request.provenance}});
  return json;
}

}  // namespace

ToleranceOutcome run(const ToleranceRequest& given) {
  check_request(given);
  ToleranceRequest request = given;
  if (request.variables.empty()) request.variables = request.problem->variables();  // as a study's
  // Under mpirun each rank solves its own members, the solvers' sums spanning every rank
  // (docs/mpi.md); the whole problem is what the report describes.
  const RankShare share(*request.problem);
  const Problem& problem = share.problem();
  const State initial = problem.initial_state();

  ToleranceOutcome outcome;
  Reference reference;
  try {
    reference = compute_reference(problem, request.reference, initial, request.t_end, request.variables);
    outcome.study = run_tolerance_study(runs_of(request, problem, initial), problem.measured(reference.state, request.t_end),
                                        reference.error_estimate, request.variables);
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": " + e.what());
  }
  if (distribution().rank() != 0) return outcome;  // rank 0 reports (src/mpi/session.hpp)

  outcome.reported = true;
  if (request.check) outcome.verdict = check_proportionality(outcome.study, request.check->exponent, request.check->tolerance);
  const Problem& whole = *request.problem;
  const std::string header = "case " + whole.name() + " · integrator " + request.integrator + " by tolerance · reference " +
                             reference.kind + " (" + reference.detail + ")\n" +
                             count_text(whole.members(), member_nouns(whole)) + " · t_end = " + printf_string("%.6g", request.t_end) + " after t0";
  outcome.table = format_tolerance_table(header, outcome.study, outcome.verdict);
  outcome.report = report_of(request, outcome, reference);
  return outcome;
}

}  // namespace dlpverify
