#include "dlpverify/study.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "dlpverify/errors.hpp"
#include "dlpverify/integrator.hpp"
#include "io/format.hpp"

namespace dlpverify {

std::vector<long> level_steps(const StudyPlan& plan) {
  std::vector<long> steps;
  for (int k = 0; k < plan.levels; ++k) {
    const double exact = plan.t_end / plan.coarsest_dt * std::pow(plan.ratio, k);
    const double whole = std::round(exact);
    if (!(whole >= 1.0) || std::abs(exact - whole) > 1e-9 * whole || whole > 1e12) {
      if (k == 0)
        throw InputError("time step", value_text(plan.coarsest_dt),
                         "t-end / dt = " + value_text(exact) + " is not a whole number of steps");
      throw InputError("step ratio", value_text(plan.ratio),
                       "level " + std::to_string(k) + " would take " + value_text(exact) + " steps, not a whole number");
    }
    steps.push_back(static_cast<long>(whole));
  }
  return steps;
}

StudyResult run_study(const StudyPlan& plan, const State& reference, const std::vector<double>& reference_error,
                      const Solve& solve) {
  StudyResult result;
  result.plan = plan;
  const std::vector<long> steps = level_steps(plan);
  const std::size_t variables = plan.variables.size();
  std::vector<std::vector<LevelErrors>> errors(variables);
  std::vector<std::vector<std::optional<double>>> differences(variables);  // ‖y_{k−1} − y_k‖
  State previous;

  for (int k = 0; k < plan.levels; ++k) {
    LevelResult level;
    level.level = k;
    level.steps = steps[k];
    // Δt_k = t_end / n_k exactly, so n_k steps land on t_end whatever the ratio.
    level.dt = plan.t_end / static_cast<double>(steps[k]);
    const auto start = std::chrono::steady_clock::now();
    State state = solve(level.dt, level.steps, level.solver_statistics);
    level.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (std::size_t v = 0; v < variables; ++v) {
      level.norms.push_back(error_norms(state, reference, plan.variables[v]));
      errors[v].push_back({level.dt, level.steps, level.norms.back().l2, level.norms.back().reference_l2});
      differences[v].push_back(k == 0 ? std::nullopt
                                      : std::optional<double>(error_norms(previous, state,
                                                                          plan.variables[v]).l2));
    }
    result.levels.push_back(std::move(level));
    if (k + 1 == plan.levels)
      result.finest = std::move(state);
    else
      previous = std::move(state);
  }

  OrderRules rules;
  rules.ratio = plan.ratio;
  rules.expected_order = plan.expected_order;
  for (std::size_t v = 0; v < variables; ++v) {
    result.orders.push_back(analyse_order(errors[v], rules));
    result.self_convergence.push_back(
        analyse_self_convergence(differences[v], result.levels.back().norms[v].reference_l2, plan.ratio));
  }

  result.reference.error = reference_error;
  result.reference.error.resize(variables, 0.0);
  for (std::size_t v = 0; v < variables; ++v) {
    const double finest = errors[v].back().error;
    const double margin = result.reference.error[v] > 0.0 ? finest / result.reference.error[v]
                                                          : std::numeric_limits<double>::infinity();
    result.reference.margin.push_back(margin);
    result.reference.trusted = result.reference.trusted && margin >= kMinimumReferenceMargin;
  }
  return result;
}

StudyResult run_study(const Problem& problem, Integrator& integrator, StudyPlan plan) {
  if (plan.variables.empty()) plan.variables = problem.variables();
  if (plan.expected_order == 0.0) plan.expected_order = integrator.order();
  const State initial = problem.initial_state();
  const State reference = problem.measured(problem.closed_form(initial, plan.t_end), plan.t_end);
  const Solve solve = [&](double dt, long steps, nlohmann::json& statistics) {
    State state = initial;
    integrator.advance(problem, state, problem.initial_time(), dt, steps);
    statistics = integrator.statistics();
    return problem.measured(state, plan.t_end);
  };
  return run_study(plan, reference, std::vector<double>(plan.variables.size(), 0.0), solve);
}

}  // namespace dlpverify
