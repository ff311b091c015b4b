#include "dlpverify/extended_study.hpp"

#include "dlpverify/errors.hpp"
#include "dlpverify/extended.hpp"
#include "dlpverify/extended_runge_kutta.hpp"

namespace dlpverify {

namespace {

const ButcherMethod& butcher_method(const Integrator& integrator) {
  if (const auto* method = dynamic_cast<const ButcherMethod*>(&integrator)) return *method;
  refuse_double_only(integrator.name());
}

}  // namespace

StudyResult run_extended_study(const Problem& problem, const Integrator& integrator, StudyPlan plan,
                               const ReferenceSettings& settings, const StudyProgress& progress, Reference* used) {
  const ButcherMethod& tableau = butcher_method(integrator);
  if (settings.kind != ReferenceKind::extended)
    throw InputError("reference", reference_kind_name(settings.kind),
                     "is computed in double, and would be the floor of a study in extended precision: use extended");
  if (problem.capability<ExtendedRhs>() == nullptr)
    throw InputError("precision", "extended",
                     "needs the case's right-hand side in extended precision, which " + problem.name() + " does not offer");
  check_plan(plan);
  if (plan.variables.empty()) plan.variables = problem.variables();
  check_expected_orders(plan);
  if (plan.expected_order == 0.0) plan.expected_order = integrator.order();
  // Its coefficients last: a tableau file that misses a condition warns as it hands them over.
  const ExtendedRungeKutta method(tableau.butcher());
  Reference reference = compute_reference(problem, settings, problem.initial_state(), plan.t_end, plan.variables);

  const ExtendedState initial(problem.initial_state());
  const ExtendedSolve solve = [&](long steps, SolverStatistics& statistics) {
    ExtendedState state = initial;
    // Δt_k = t_end / steps in Extended: the levels end at t0 + t_end to ε_Extended.
    method.advance(problem, state, Extended(problem.initial_time()), Extended(plan.t_end) / static_cast<double>(steps),
                   steps);
    statistics = SolverStatistics{};
    statistics.steps = steps;
    statistics.rhs_evals = steps * static_cast<long>(method.stages());
    return state;
  };
  StudyResult study = run_study(plan, *reference.extended, reference.error_estimate, solve, progress);
  if (used) *used = std::move(reference);
  return study;
}

}  // namespace dlpverify
