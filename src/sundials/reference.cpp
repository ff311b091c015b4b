#include "dlpverify/reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/manufactured.hpp"
#include "dlpverify/norms.hpp"
#include "dlpverify/solution_features.hpp"
#include "harness/distribution.hpp"
#include "harness/sub_population.hpp"
#include "io/format.hpp"
#include "io/progress.hpp"
#include "integrators/sundials/cvode_integrator.hpp"

namespace dlpverify {

namespace {

constexpr Eigen::Index kReferenceBlock = 1024;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One block from τ = tau_from to tau_from + duration, restarting at the block's kinks if asked.
void solve_block(CvodeIntegrator& cvode, const Problem& problem, State& block, const std::vector<double>& kinks,
                 double t0, double tau_from, double duration) {
  std::vector<double> stops;
  for (double kink : kinks)
    if (std::isfinite(kink) && kink > tau_from && kink < tau_from + duration) stops.push_back(kink);
  std::sort(stops.begin(), stops.end());
  stops.push_back(tau_from + duration);
  double reached = tau_from;
  for (double stop : stops) {
    if (stop <= reached) continue;
    cvode.advance(problem, block, t0 + reached, stop - reached, 1);  // no step longer than the segment
    reached = stop;
  }
}

// solve_with_cvode, its blocks counted on the progress line as `what` ("reference block", …).
State solve_in_blocks(const Problem& problem, const State& from, double tau_from, double duration,
                      const ReferenceSettings& settings, nlohmann::json& statistics, const State* scale_from,
                      const char* what) {
  CvodeSettings cvode;
  cvode.rtol = settings.rtol;
  cvode.atol = absolute_tolerances(problem, scale_from ? *scale_from : from, settings.rtol);
  cvode.method = CvodeMethod::adams;  // non-stiff problems; its step sequence is also the most reproducible
  cvode.max_steps = settings.max_steps;
  // Adams orders above 7 cost more than they save here: on `full` at rtol 1e-13 (the error
  // estimate's solve) CVODE took 15 % more steps with order 8 allowed than with 7, and each step's
  // Nordsieck update costs ~q²/2 vector sums. At rtol 1e-12 no block went above order 7.
  cvode.max_order = 7;
  cvode.openmp_vector = false;  // the threads share out blocks instead
  const double t0 = problem.initial_time();

  const Eigen::Index members = from.rows();
  const Eigen::Index blocks = (members + kReferenceBlock - 1) / kReferenceBlock;
  std::vector<double> kinks(static_cast<std::size_t>(members), std::nan(""));
  if (settings.restart_at_kinks) kinks = kink_times(problem, from);
  State result(members, from.cols());
  long steps_max = 0;
  SolverStatistics total;  // the blocks' counts added
  std::exception_ptr failure;
  progress::Task task(what, static_cast<long>(blocks));
#pragma omp parallel
  {
    CvodeIntegrator integrator(cvode);
    State block;
#pragma omp for schedule(dynamic)
    for (Eigen::Index b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * kReferenceBlock;
      const Eigen::Index count = std::min(kReferenceBlock, members - first);
      block = from.middleRows(first, count);
      const std::vector<double> block_kinks(kinks.begin() + first, kinks.begin() + first + count);
      try {
        const SubPopulation part(problem, first, count);
        solve_block(integrator, part, block, block_kinks, t0, tau_from, duration);
      } catch (...) {
#pragma omp critical(dlpverify_reference_failure)
        if (!failure) failure = std::current_exception();
        continue;
      }
      result.middleRows(first, count) = block;
      const SolverStatistics counts = integrator.statistics();
#pragma omp critical(dlpverify_reference_statistics)
      {
        steps_max = std::max(steps_max, counts.steps.value_or(0));
        total += counts;
      }
      task.advance();
    }
  }
  if (failure) std::rethrow_exception(failure);
  // Under MPI the counts are every process's (harness/distribution.hpp); serially these are the identity.
  const Distribution& all = distribution();
  statistics = {{"method", "adams"},          {"rtol", settings.rtol},          {"max_order", cvode.max_order},
                {"blocks", all.sum(static_cast<long>(blocks))}, {"particles_per_block", kReferenceBlock},
                {"steps_max", all.max(steps_max)},     {"steps_total", all.sum(total.steps.value_or(0))},
                {"rhs_evals_total", all.sum(total.rhs_evals.value_or(0))}};
  return result;
}

const char* closed_form_hint(ReferenceKind kind) {
  return kind == ReferenceKind::manufactured
             ? "a manufactured reference needs the manufactured problem, whose closed form is its trajectory"
             : "use a CVODE or an integrator reference";
}

void require_closed_form(const Problem& problem, ReferenceKind kind) {
  if (!has_closed_form(problem))
    throw InputError("reference", reference_kind_name(kind),
                     "case " + problem.name() + " has no closed form; " + closed_form_hint(kind));
}

void require_integrator(const ReferenceSettings& settings) {
  if (!settings.integrator) throw InputError("reference", "integrator", "no integrator given");
  if (!std::isfinite(settings.dt) || settings.dt <= 0.0)
    throw InputError("reference", "integrator", "its step dt = " + value_text(settings.dt) + " must be positive and finite");
}

// t_end / dt whole by the rule of level_steps (1e-9 relative), or InputError naming the reference.
long reference_steps(double t_end, double dt) {
  StudyPlan one_level;
  one_level.t_end = t_end;
  one_level.coarsest_dt = dt;
  one_level.levels = 1;
  try {
    return level_steps(one_level).front();
  } catch (const InputError& e) {
    throw InputError("reference", "integrator at dt = " + value_text(dt), e.reason());
  }
}

// The integrator at dt, and again at dt/2: the error of the dt solve is estimated per measured
// variable by Richardson's rule. With y_dt − y = C dt^p and y_{dt/2} − y = C (dt/2)^p,
// ‖y_dt − y‖ = ‖y_dt − y_{dt/2}‖ · 2^p / (2^p − 1). An integrator of unknown order (p = 0) gets
// twice the difference, the factor of p = 1, the largest of every p ≥ 1.
Reference integrator_reference(const Problem& problem, const ReferenceSettings& settings, const State& initial,
                               double t_end, const std::vector<Variable>& variables) {
  require_integrator(settings);
  Integrator& integrator = *settings.integrator;
  const long steps = reference_steps(t_end, settings.dt);
  const double t0 = problem.initial_time();
  const auto start = std::chrono::steady_clock::now();
  Reference reference;
  reference.state = initial;
  integrator.advance(problem, reference.state, t0, t_end / static_cast<double>(steps), steps);
  const SolverStatistics first = integrator.statistics();
  const double first_seconds = seconds_since(start);
  State halved = initial;
  integrator.advance(problem, halved, t0, t_end / static_cast<double>(2 * steps), 2 * steps);
  const SolverStatistics second = integrator.statistics();

  const int order = integrator.order();
  const double factor = halved_step_error_factor(order);
  const State measured = problem.measured(reference.state, t_end), measured_halved = problem.measured(halved, t_end);
  reference.error_estimate = halved_step_error(measured, measured_halved, variables, order);

  char detail[320];
  if (order > 0)
    std::snprintf(detail, sizeof detail,
                  "%s at dt = %s, error estimated against dt/2: the difference x 2^%d/(2^%d - 1)",
                  integrator.name().c_str(), value_text(settings.dt).c_str(), order, order);
  else
    std::snprintf(detail, sizeof detail,
                  "%s at dt = %s, error estimated against dt/2: its order is unknown, the difference x 2",
                  integrator.name().c_str(), value_text(settings.dt).c_str());
  reference.kind = reference_kind_name(ReferenceKind::integrator);
  reference.detail = detail;
  reference.statistics = {{"integrator", integrator.name()},
                          {"order", order},
                          {"dt", settings.dt},
                          {"steps", steps},
                          {"error_estimate_factor", factor},
                          {"wall_s", first_seconds},
                          {"solve", first},
                          {"error_estimate_solve", second},
                          {"error_estimate_wall_s", seconds_since(start) - first_seconds}};
  return reference;
}

}  // namespace

double halved_step_error_factor(int order) {
  return order > 0 ? std::ldexp(1.0, order) / (std::ldexp(1.0, order) - 1.0) : 2.0;
}

std::vector<double> halved_step_error(const State& solution, const State& halved, const std::vector<Variable>& variables,
                                      int order) {
  std::vector<double> error;
  for (const Variable& v : variables) error.push_back(halved_step_error_factor(order) * error_norms(solution, halved, v).l2);
  return error;
}

const char* reference_kind_name(ReferenceKind kind) {
  switch (kind) {
    case ReferenceKind::exact: return "exact";
    case ReferenceKind::cvode: return "cvode";
    case ReferenceKind::integrator: return "integrator";
    case ReferenceKind::manufactured: return "manufactured";
  }
  return "unknown";
}

State solve_with_cvode(const Problem& problem, const State& from, double tau_from, double duration,
                       const ReferenceSettings& settings, nlohmann::json& statistics, const State* scale_from) {
  return solve_in_blocks(problem, from, tau_from, duration, settings, statistics, scale_from, "CVODE block");
}

void check_reference_settings(const ReferenceSettings& settings) {
  if (!std::isfinite(settings.rtol) || settings.rtol < kTightestReferenceRtol || settings.rtol >= 1e-3)
    throw InputError("reference relative tolerance", value_text(settings.rtol), "must lie in [1e-14, 1e-3)");
  if (settings.max_steps < 1 || settings.max_steps > kMostCvodeSteps)
    throw InputError("CVODE step limit", std::to_string(settings.max_steps), "must lie in [1, 1e9]");
}

std::optional<ReferenceSettings> tightened_reference(const ReferenceSettings& settings, double ratio) {
  ReferenceSettings tighter = settings;
  switch (settings.kind) {
    case ReferenceKind::cvode:
      if (settings.rtol <= kTightestReferenceRtol) return std::nullopt;
      tighter.rtol = std::max(settings.rtol / 100.0, kTightestReferenceRtol);
      return tighter;
    case ReferenceKind::integrator:
      if (ratio < 2.0 || ratio != std::round(ratio)) return std::nullopt;
      tighter.dt = settings.dt / ratio;
      return tighter;
    case ReferenceKind::exact:
    case ReferenceKind::manufactured: return std::nullopt;
  }
  return std::nullopt;
}

Reference compute_reference(const Problem& problem, const ReferenceSettings& settings, const State& initial,
                            double t_end, const std::vector<Variable>& variables) {
  Reference reference;
  const auto start = std::chrono::steady_clock::now();
  if (settings.kind == ReferenceKind::exact || settings.kind == ReferenceKind::manufactured) {
    require_closed_form(problem, settings.kind);
    reference.state = closed_form(problem, initial, t_end);
    reference.kind = reference_kind_name(settings.kind);
    reference.detail = reference_detail(problem);
    reference.error_estimate.assign(variables.size(), 0.0);
    reference.statistics = {{"wall_s", seconds_since(start)}};
    return reference;
  }
  if (settings.kind == ReferenceKind::integrator) return integrator_reference(problem, settings, initial, t_end, variables);

  nlohmann::json first, second;
  reference.state = solve_in_blocks(problem, initial, 0.0, t_end, settings, first, nullptr, "reference block");
  const double first_seconds = seconds_since(start);
  ReferenceSettings tighter_settings = settings;
  tighter_settings.rtol = settings.rtol / 10.0;
  const State tighter = solve_in_blocks(problem, initial, 0.0, t_end, tighter_settings, second, nullptr,
                                        "reference error estimate (rtol/10) block");
  const State measured = problem.measured(reference.state, t_end), measured_tighter = problem.measured(tighter, t_end);
  for (const Variable& v : variables) reference.error_estimate.push_back(error_norms(measured, measured_tighter, v).l2);

  char detail[160];
  std::snprintf(detail, sizeof detail, "CVODE Adams, rtol %.0e, atol rtol x field scale; error estimated against rtol %.0e",
                settings.rtol, settings.rtol / 10.0);
  reference.kind = "cvode";
  reference.detail = detail;
  reference.statistics = {{"rtol", settings.rtol},
                          {"wall_s", first_seconds},
                          {"solve", first},
                          {"error_estimate_solve", second},
                          {"error_estimate_wall_s", seconds_since(start) - first_seconds}};
  return reference;
}

std::function<State(double tau)> reference_trajectory(const Problem& problem, const ReferenceSettings& settings,
                                                      const State& initial) {
  if (settings.kind == ReferenceKind::exact || settings.kind == ReferenceKind::manufactured) {
    require_closed_form(problem, settings.kind);
    return [&problem, &initial](double tau) { return closed_form(problem, initial, tau); };
  }
  struct Continued {
    State state;
    double tau = 0.0;
  };
  auto last = std::make_shared<Continued>(Continued{initial, 0.0});
  if (settings.kind == ReferenceKind::integrator) {
    require_integrator(settings);
    return [last, &problem, settings](double tau) {
      if (tau > last->tau) {
        // Δτ in ⌈Δτ/dt⌉ equal steps: output times need not be multiples of dt, and no step is longer.
        const double span = tau - last->tau;
        const long steps = std::max(1L, static_cast<long>(std::ceil(span / settings.dt * (1.0 - 1e-12))));
        settings.integrator->advance(problem, last->state, problem.initial_time() + last->tau, span / static_cast<double>(steps),
                                     steps);
        last->tau = tau;
      }
      return last->state;
    };
  }
  return [last, &problem, settings](double tau) {
    if (tau > last->tau) {
      nlohmann::json ignored;
      last->state = solve_in_blocks(problem, last->state, last->tau, tau - last->tau, settings, ignored, nullptr,
                                    "reference history block");
      last->tau = tau;
    }
    return last->state;
  };
}

StudyResult run_study_with(const Problem& problem, Integrator& integrator, StudyPlan plan,
                           const ReferenceSettings& settings, const LevelRunner& run_levels, Reference* used) {
  // A manufactured reference belongs to the manufactured problem: a problem given as it is is
  // wrapped here, over the study's duration (dlpverify/manufactured.hpp).
  if (settings.kind == ReferenceKind::manufactured && !is_manufactured(problem)) {
    const ManufacturedProblem manufactured(problem, plan.t_end);
    return run_study_with(manufactured, integrator, std::move(plan), settings, run_levels, used);
  }
  if (plan.variables.empty()) plan.variables = problem.variables();
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
  const LevelRunner levels = [&progress](const StudyPlan& p, const State& reference,
                                         const std::vector<double>& reference_error, const Solve& solve,
                                         const TightenReference&) {
    return run_study(p, reference, reference_error, solve, progress);
  };
  return run_study_with(problem, integrator, std::move(plan), settings, levels, used);
}

}  // namespace dlpverify
