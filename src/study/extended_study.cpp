#include "dlpverify/extended_study.hpp"

#include "dlpverify/errors.hpp"
#include "dlpverify/extended.hpp"
#include "dlpverify/extended_runge_kutta.hpp"

namespace dlpverify {

namespace {

std::string integrator_refusal(const Integrator& integrator) {
  const auto* method = dynamic_cast<const ButcherMethod*>(&integrator);
  return method == nullptr || !method->has_explicit_tableau() ? double_only(integrator.name()) : "";
}

std::string problem_refusal(const Problem& problem) {
  return problem.capability<ExtendedRhs>() == nullptr
             ? "needs the case's right-hand side in extended precision, which " + problem.name() + " does not offer"
             : "";
}

}  // namespace

std::string extended_refusal(const Problem& problem, const Integrator& integrator) {
  const std::string refusal = integrator_refusal(integrator);
  return refusal.empty() ? problem_refusal(problem) : refusal;
}

StudyResult run_extended_study(const Problem& problem, const Integrator& integrator, StudyPlan plan,
                               const ReferenceSettings& settings, const StudyProgress& progress, Reference* used) {
  if (const std::string refusal = integrator_refusal(integrator); !refusal.empty())
    throw InputError("precision", "extended", refusal);
  if (settings.kind != ReferenceKind::extended)
    throw InputError("reference", reference_kind_name(settings.kind),
                     "is computed in double, and would be the floor of a study in extended precision: use extended");
  if (const std::string refusal = problem_refusal(problem); !refusal.empty())
    throw InputError("precision", "extended", refusal);
  const auto& tableau = dynamic_cast<const ButcherMethod&>(integrator);
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
