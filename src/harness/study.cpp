#include "dlpverify/study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/extended.hpp"
#include "dlpverify/extended_study.hpp"
#include "dlpverify/integrator.hpp"
#include "io/format.hpp"
#include "io/progress.hpp"

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

double expected_order_of(const StudyPlan& plan, std::size_t v) {
  const auto own = plan.expected_order_by_variable.find(plan.variables[v].name);
  return own != plan.expected_order_by_variable.end() ? own->second : plan.expected_order;
}

void check_expected_orders(const StudyPlan& plan) {
  for (const auto& expected : plan.expected_order_by_variable) {
    const std::string& name = expected.first;  // a lambda captures a name, not a structured binding (clang 14)
    const double order = expected.second;
    const bool measured = std::any_of(plan.variables.begin(), plan.variables.end(),
                                      [&name](const Variable& v) { return v.name == name; });
    if (!measured) {
      std::string names;
      for (const Variable& v : plan.variables) names += (names.empty() ? "" : ", ") + v.name;
      throw InputError("expected order", name + "=" + value_text(order), "names no measured variable (" + names + ")");
    }
    if (!std::isfinite(order) || order <= 0.0)
      throw InputError("expected order", name + "=" + value_text(order), "must be positive and finite");
  }
}

void check_plan(const StudyPlan& plan, int fewest_levels) {
  if (!std::isfinite(plan.t_end) || plan.t_end <= 0.0)
    throw InputError("duration", value_text(plan.t_end), "must be positive and finite");
  if (!std::isfinite(plan.coarsest_dt) || plan.coarsest_dt <= 0.0)
    throw InputError("time step", value_text(plan.coarsest_dt), "must be positive and finite");
  if (plan.levels < fewest_levels)
    throw InputError("levels", std::to_string(plan.levels), "must be at least " + std::to_string(fewest_levels));
  if (plan.levels > kMostLevels)
    throw InputError("levels", std::to_string(plan.levels), "must be at most " + std::to_string(kMostLevels));
  if (!std::isfinite(plan.ratio) || plan.ratio <= 1.0)
    throw InputError("step ratio", value_text(plan.ratio), "must be finite and greater than 1");
  level_steps(plan);
}

namespace {

// Level k solved: n_k steps of Δt_k = t_end / n_k (exactly, so n_k steps land on t_end whatever
// the ratio), timed, measured against the reference. Leaves the level's state in `state`.
// `solve(steps, statistics)` steps States of either arithmetic.
template <class States, class SolveSteps>
LevelResult solve_level(const StudyPlan& plan, int k, long steps, const States& reference, const SolveSteps& solve,
                        States& state, const States* previous) {
  SolverStatistics statistics;
  const auto start = std::chrono::steady_clock::now();
  state = solve(steps, statistics);
  const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  LevelResult level = measure_level(plan, k, steps, state, reference, previous);
  level.wall_seconds = wall_seconds;
  level.solver_statistics = std::move(statistics);
  return level;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A level an earlier run finished must be a level of this plan, with a value for every variable.
void check_done_level(const StudyPlan& plan, const std::vector<long>& steps, const LevelResult& level, int k) {
  const std::size_t variables = plan.variables.size();
  if (k >= plan.levels || level.level != k || level.steps != steps[k] ||
      !same_bits(level.dt, plan.t_end / static_cast<double>(steps[k])) || level.norms.size() != variables ||
      level.self_difference.size() != variables)
    throw InputError("resumed level", std::to_string(k), "is not level " + std::to_string(k) + " of this study");
}

// The last finished level's state, solved again; its norms must be the ones it was finished with,
// or the levels taken over were not this computation's.
template <class States, class SolveSteps>
States solve_again(const StudyPlan& plan, const LevelResult& done, const States& reference, const SolveSteps& solve) {
  States state;
  const LevelResult again = solve_level(plan, done.level, done.steps, reference, solve, state, static_cast<const States*>(nullptr));
  for (std::size_t v = 0; v < plan.variables.size(); ++v) {
    const ErrorNorms &a = again.norms[v], &b = done.norms[v];
    if (!(same_bits(a.l2, b.l2) && same_bits(a.rms, b.rms) && same_bits(a.relative, b.relative) &&
          same_bits(a.max, b.max) && same_bits(a.reference_l2, b.reference_l2)))
      throw InputError("resumed level", std::to_string(done.level),
                       "solved again, its " + plan.variables[v].name + " L2 error is " + shortest_text(a.l2) +
                           ", not the " + shortest_text(b.l2) +
                           " it was finished with: the levels taken over are not from this computation");
  }
  return state;
}

// Δt_k = t_end / n_k in double, for a Solve.
auto by_steps(const StudyPlan& plan, const Solve& solve) {
  return [&plan, &solve](long steps, SolverStatistics& statistics) {
    return solve(plan.t_end / static_cast<double>(steps), steps, statistics);
  };
}

// The finest state in double, as a study result holds it.
State in_double(State state) { return state; }
State in_double(const ExtendedState& state) { return state.high(); }

}  // namespace

namespace {

// measure_level for states of either arithmetic (error_norms has both).
template <class States>
LevelResult measure_level_of(const StudyPlan& plan, int k, long steps, const States& state, const States& reference,
                             const States* previous) {
  LevelResult level;
  level.level = k;
  level.steps = steps;
  level.dt = plan.t_end / static_cast<double>(steps);
  for (const Variable& variable : plan.variables) {
    level.norms.push_back(error_norms(state, reference, variable));
    level.self_difference.push_back(previous ? std::optional<double>(error_norms(*previous, state, variable).l2)
                                             : std::nullopt);
  }
  return level;
}

}  // namespace

LevelResult measure_level(const StudyPlan& plan, int k, long steps, const State& state, const State& reference,
                          const State* previous) {
  return measure_level_of(plan, k, steps, state, reference, previous);
}

LevelResult measure_level(const StudyPlan& plan, int k, long steps, const ExtendedState& state,
                          const ExtendedState& reference, const ExtendedState* previous) {
  return measure_level_of(plan, k, steps, state, reference, previous);
}

void analyse_levels(StudyResult& result, const std::vector<double>& reference_error) {
  const StudyPlan& plan = result.plan;
  OrderRules rules;
  rules.ratio = plan.ratio;
  rules.epsilon = epsilon_of(plan.precision);
  for (std::size_t v = 0; v < plan.variables.size(); ++v) {
    rules.expected_order = expected_order_of(plan, v);
    rules.reference_error = v < reference_error.size() ? reference_error[v] : 0.0;
    std::vector<LevelErrors> errors;
    std::vector<std::optional<double>> differences;
    for (const LevelResult& level : result.levels) {
      errors.push_back({level.dt, level.steps, level.norms[v].l2, level.norms[v].reference_l2});
      differences.push_back(level.self_difference[v]);
    }
    result.orders.push_back(analyse_order(errors, rules));
    result.self_convergence.push_back(
        analyse_self_convergence(differences, result.levels.back().norms[v].reference_l2, plan.ratio));
  }

  result.reference.error = reference_error;
  result.reference.error.resize(plan.variables.size(), 0.0);
  for (std::size_t v = 0; v < plan.variables.size(); ++v) {
    const double finest = result.levels.back().norms[v].l2;
    const double margin = result.reference.error[v] > 0.0 ? finest / result.reference.error[v]
                                                          : std::numeric_limits<double>::infinity();
    result.reference.margin.push_back(margin);
    result.reference.trusted = result.reference.trusted && margin >= kMinimumReferenceMargin;
  }
}

StudyResult analyse_study(const StudyPlan& plan, std::vector<LevelResult> levels,
                          const std::vector<double>& reference_error, State finest) {
  StudyResult result;
  result.plan = plan;
  result.levels = std::move(levels);
  result.finest = std::move(finest);
  analyse_levels(result, reference_error);
  return result;
}

LevelResult run_level(const StudyPlan& plan, int k, long steps, const State& reference, const Solve& solve,
                      const State* previous, State& state) {
  return solve_level(plan, k, steps, reference, by_steps(plan, solve), state, previous);
}

namespace {

// The fixed levels of a study in either arithmetic: those a journal finished taken over, the
// others solved, each handed to progress.finished; progress.stop asked before each.
template <class States, class SolveSteps>
StudyResult run_levels(const StudyPlan& plan, const States& reference, const std::vector<double>& reference_error,
                       const SolveSteps& solve, const StudyProgress& progress) {
  check_plan(plan);  // a fit needs two levels, and a ratio above 1 refines them
  check_expected_orders(plan);
  StudyResult result;
  result.plan = plan;
  const std::vector<long> steps = level_steps(plan);
  const int done = static_cast<int>(progress.done.size());
  const auto stop_before = [&progress](int levels_done) {
    if (progress.stop && progress.stop()) throw StudyStopped(levels_done);
  };
  States previous;  // the state of the level before k (after the loop: the finest)
  // A level's cost grows with its steps; levels taken over from a journal cost nothing.
  std::vector<double> weights(steps.begin(), steps.end());
  for (int k = 0; k < done && k < plan.levels; ++k) weights[k] = 0.0;
  dlpverify::progress::Task task("level", plan.levels, weights);

  for (int k = 0; k < plan.levels; ++k) {
    if (k > 0) task.advance();  // level k - 1 finished
    if (k < done) {
      check_done_level(plan, steps, progress.done[k], k);
      result.levels.push_back(progress.done[k]);
      if (k + 1 == done) {
        stop_before(done);
        previous = solve_again(plan, progress.done[k], reference, solve);
      }
      continue;
    }
    stop_before(k);
    States state;
    LevelResult level = solve_level(plan, k, steps[k], reference, solve, state, k == 0 ? nullptr : &previous);
    if (progress.finished) progress.finished(level);
    result.levels.push_back(std::move(level));
    previous = std::move(state);
  }
  if (done > plan.levels) check_done_level(plan, steps, progress.done[plan.levels], plan.levels);
  return analyse_study(plan, std::move(result.levels), reference_error, in_double(std::move(previous)));
}

}  // namespace

StudyResult run_study(const StudyPlan& plan, const State& reference, const std::vector<double>& reference_error,
                      const Solve& solve, const StudyProgress& progress) {
  return run_levels(plan, reference, reference_error, by_steps(plan, solve), progress);
}

StudyResult run_study(const StudyPlan& plan, const ExtendedState& reference, const std::vector<double>& reference_error,
                      const ExtendedSolve& solve, const StudyProgress& progress) {
  return run_levels(plan, reference, reference_error, solve, progress);
}

StudyResult run_study(const Problem& problem, Integrator& integrator, StudyPlan plan) {
  check_plan(plan);  // before the reference is computed
  if (plan.variables.empty()) plan.variables = problem.variables();
  check_expected_orders(plan);
  if (plan.expected_order == 0.0) plan.expected_order = integrator.order();
  const State initial = problem.initial_state();
  const State reference = problem.measured(closed_form(problem, initial, plan.t_end), plan.t_end);
  const Solve solve = [&](double dt, long steps, SolverStatistics& statistics) {
    State state = initial;
    integrator.advance(problem, state, problem.initial_time(), dt, steps);
    statistics = integrator.statistics();
    return problem.measured(state, plan.t_end);
  };
  return run_study(plan, reference, std::vector<double>(plan.variables.size(), 0.0), solve);
}

}  // namespace dlpverify
