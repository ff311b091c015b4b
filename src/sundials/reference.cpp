#include "dlpverify/reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/norms.hpp"
#include "dlpverify/solution_features.hpp"
#include "harness/sub_population.hpp"
#include "io/progress.hpp"
#include "sundials/cvode_integrator.hpp"

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
  long steps_max = 0, steps_total = 0, rhs_evals_total = 0;
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
      const nlohmann::json counts = integrator.statistics();
#pragma omp critical(dlpverify_reference_statistics)
      {
        steps_max = std::max(steps_max, counts.value("steps", 0L));
        steps_total += counts.value("steps", 0L);
        rhs_evals_total += counts.value("rhs_evals", 0L);
      }
      task.advance();
    }
  }
  if (failure) std::rethrow_exception(failure);
  statistics = {{"method", "adams"},          {"rtol", settings.rtol},          {"max_order", cvode.max_order},
                {"blocks", blocks},           {"particles_per_block", kReferenceBlock},
                {"steps_max", steps_max},     {"steps_total", steps_total},
                {"rhs_evals_total", rhs_evals_total}};
  return result;
}

}  // namespace

State solve_with_cvode(const Problem& problem, const State& from, double tau_from, double duration,
                       const ReferenceSettings& settings, nlohmann::json& statistics, const State* scale_from) {
  return solve_in_blocks(problem, from, tau_from, duration, settings, statistics, scale_from, "CVODE block");
}

Reference compute_reference(const Problem& problem, const ReferenceSettings& settings, const State& initial,
                            double t_end, const std::vector<Variable>& variables) {
  Reference reference;
  const auto start = std::chrono::steady_clock::now();
  if (settings.kind == ReferenceKind::exact) {
    if (!has_closed_form(problem))
      throw InputError("reference", "exact", "case " + problem.name() + " has no closed form; use cvode");
    reference.state = closed_form(problem, initial, t_end);
    reference.kind = "exact";
    reference.detail = reference_detail(problem);
    reference.error_estimate.assign(variables.size(), 0.0);
    reference.statistics = {{"wall_s", seconds_since(start)}};
    return reference;
  }

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
  if (settings.kind == ReferenceKind::exact) {
    if (!has_closed_form(problem))
      throw InputError("reference", "exact", "case " + problem.name() + " has no closed form; use cvode");
    return [&problem, &initial](double tau) { return closed_form(problem, initial, tau); };
  }
  struct Continued {
    State state;
    double tau = 0.0;
  };
  auto last = std::make_shared<Continued>(Continued{initial, 0.0});
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

StudyResult run_study(const Problem& problem, Integrator& integrator, StudyPlan plan, const ReferenceSettings& settings) {
  if (plan.variables.empty()) plan.variables = problem.variables();
  if (plan.expected_order == 0.0) plan.expected_order = integrator.order();
  const State initial = problem.initial_state();
  const Reference reference = compute_reference(problem, settings, initial, plan.t_end, plan.variables);
  const Solve solve = [&](double dt, long steps, nlohmann::json& statistics) {
    State state = initial;
    integrator.advance(problem, state, problem.initial_time(), dt, steps);
    statistics = integrator.statistics();
    return problem.measured(state, plan.t_end);
  };
  return run_study(plan, reference.state, reference.error_estimate, solve);
}

}  // namespace dlpverify
