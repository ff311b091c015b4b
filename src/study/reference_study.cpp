// A study against a reference of any kind (dlpverify/reference_study.hpp).
#include "dlpverify/reference_study.hpp"

#include <optional>
#include <utility>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/extended_study.hpp"
#include "dlpverify/manufactured.hpp"

namespace dlpverify {

StudyResult run_study_with(const Problem& problem, Integrator& integrator, StudyPlan plan,
                           const ReferenceSettings& settings, const LevelRunner& run_levels, Reference* used) {
  check_plan(plan, 1);  // before the reference is computed; the runner asks for its own fewest levels
  // A manufactured reference belongs to the manufactured problem: a problem given as it is is
  // wrapped here, over the study's duration (dlpverify/manufactured.hpp).
  if (settings.kind == ReferenceKind::manufactured && !is_manufactured(problem)) {
    const ManufacturedProblem manufactured(problem, plan.t_end);
    return run_study_with(manufactured, integrator, std::move(plan), settings, run_levels, used);
  }
  if (plan.precision == Precision::extended)  // a level search's, which run() refuses
    return run_extended_study(problem, integrator, std::move(plan), settings, {}, used);
  if (plan.variables.empty()) plan.variables = problem.variables();
  check_expected_orders(plan);
  if (plan.expected_order == 0.0) plan.expected_order = integrator.order();
  Reference reference = compute_reference(problem, settings, problem.initial_state(), plan.t_end, plan.variables);
  // The levels are measured (Problem::measured), so the reference is too: a derived column (an
  // energy, a pressure) is compared with the same quantity, never with a raw field.
  reference.state = problem.measured(std::move(reference.state), plan.t_end);
  const Solve solve = [&](double dt, long steps, SolverStatistics& statistics) {
    State state = problem.initial_state();
    integrator.advance(problem, state, problem.initial_time(), dt, steps);
    statistics = integrator.statistics();
    return problem.measured(std::move(state), plan.t_end);
  };
  // Each tightening is computed once, from the settings of the last one (deterministic); the
  // reference reported is the tightest asked for.
  ReferenceSettings current = settings;
  Reference tightest;
  const TightenReference tighten = [&]() -> std::optional<TighterReference> {
    const std::optional<ReferenceSettings> tighter = tightened_reference(current, plan.ratio);
    if (!tighter) return std::nullopt;
    current = *tighter;
    tightest = compute_reference(problem, current, problem.initial_state(), plan.t_end, plan.variables);
    tightest.state = problem.measured(std::move(tightest.state), plan.t_end);
    return TighterReference{tightest.state, tightest.error_estimate, tightest.detail};
  };
  StudyResult study = run_levels(plan, reference.state, reference.error_estimate, solve, tighten);
  if (used) *used = tightest.kind.empty() ? std::move(reference) : std::move(tightest);
  return study;
}

StudyResult run_study(const Problem& problem, Integrator& integrator, StudyPlan plan, const ReferenceSettings& settings,
                      const StudyProgress& progress, Reference* used) {
  if (plan.precision == Precision::extended && settings.kind != ReferenceKind::manufactured)
    return run_extended_study(problem, integrator, std::move(plan), settings, progress, used);
  const LevelRunner levels = [&progress](const StudyPlan& p, const State& reference,
                                         const std::vector<double>& reference_error, const Solve& solve,
                                         const TightenReference&) {
    return run_study(p, reference, reference_error, solve, progress);
  };
  return run_study_with(problem, integrator, std::move(plan), settings, levels, used);
}

}  // namespace dlpverify
