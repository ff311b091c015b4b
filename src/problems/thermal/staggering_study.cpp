#include "problems/thermal/staggering_study.hpp"

#include <cmath>
#include <cstdio>

#include "dlpverify/splitting.hpp"
#include "integrators/implicit/staggered_solver.hpp"
#include "io/format.hpp"
#include "problems/thermal/adaptive_check.hpp"

namespace dlpverify::thermal {

namespace {

using implicit::Sweep;

constexpr double kStepTolerance = 1e-14;  // contraction: sweep to round-off
constexpr int kStepSweeps = 1000;

// Flat JSON rows as CSV, columns in `keys` order.
std::string csv_of(const nlohmann::json& rows, const std::vector<std::string>& keys) {
  std::string csv;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (i > 0) csv += ',';
    csv += keys[i];
  }
  csv += '\n';
  for (const nlohmann::json& row : rows) {
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const nlohmann::json& v = row.at(keys[i]);
      if (i > 0) csv += ',';
      if (!v.is_null()) csv += v.is_string() ? v.get<std::string>() : v.dump();
    }
    csv += '\n';
  }
  return csv;
}

// "-": too few sweeps to measure (converged within W + 1), or no known radius for this case.
std::string cell(double x, const char* format) { return std::isnan(x) ? std::string("-") : printf_string(format, x); }

nlohmann::json null_if_nan(double x) { return std::isnan(x) ? nlohmann::json() : nlohmann::json(x); }

}  // namespace

StaggeringReport contraction_study(const Problem& problem, Sweep sweep, const std::vector<double>& steps) {
  const auto* coupled = problem.capability<SweepContraction>();
  const State y = problem.initial_state();
  implicit::StaggeredSolver solver(problem, sweep, y);
  const std::vector<double> tolerance(solver.blocks().size(), kStepTolerance);
  StaggeringReport report;
  appendf(report.text, "%s: one backward-Euler step from the initial state, %s sweeps (contraction over %d sweeps)\n",
          problem.name().c_str(), implicit::sweep_name(sweep).c_str(), solver.window());
  appendf(report.text, "%12s %7s %16s %16s %12s\n", "dt", "sweeps", "contraction", "spectral radius", "rel. diff.");
  nlohmann::json rows = nlohmann::json::array();
  State w;
  for (double dt : steps) {
    const implicit::StaggeredIteration it = solver.step(y, problem.initial_time(), dt, tolerance, kStepSweeps, w);
    const double radius = coupled ? (sweep == Sweep::jacobi ? coupled->jacobi_radius(dt) : coupled->gauss_seidel_radius(dt))
                                  : std::nan("");
    const double difference = std::abs(it.contraction - radius) / radius;
    appendf(report.text, "%12.6g %7d %16s %16s %12s  %s\n", dt, it.sweeps, cell(it.contraction, "%.10f").c_str(),
            cell(radius, "%.10f").c_str(), cell(difference, "%.3g").c_str(),
            it.converged ? "converged" : it.diverged ? "DIVERGES" : "not converged");
    rows.push_back({{"dt", dt}, {"sweeps", it.sweeps}, {"contraction", null_if_nan(it.contraction)},
                    {"spectral_radius", coupled ? nlohmann::json(radius) : nlohmann::json()},
                    {"converged", it.converged}, {"diverged", it.diverged}});
    if (!it.converged && !report.failed_step) {
      report.failed_step = dt;
      if (!it.failed_block.empty())  // no contraction to measure: a block's own solve failed first
        report.failure = printf_string("the backward-Euler solve of block %s does not settle in sweep %d: its "
                                       "fixed-point iteration converges only while dt |df/dy| < 1, so take a smaller step",
                                       it.failed_block.c_str(), it.sweeps);
      else
        report.failure = printf_string("the staggered iteration %s after %d sweeps: measured contraction %.6g per sweep",
                                       it.diverged ? "diverges" : "does not converge", it.sweeps, it.contraction);
      if (coupled && it.failed_block.empty())
        report.failure += ", spectral radius " +
                          (sweep == Sweep::jacobi ? coupled->jacobi_radius_formula() : coupled->gauss_seidel_radius_formula()) +
                          " = " + value_text(radius) + "; it converges only for dt < " + value_text(coupled->step_limit());
    }
  }
  report.passed = !report.failed_step;
  report.result = {{"case", problem.name()}, {"mode", "contraction"}, {"sweep", implicit::sweep_name(sweep)},
                   {"window", solver.window()}, {"rows", rows}};
  report.csv = csv_of(rows, {"dt", "sweeps", "contraction", "spectral_radius", "converged", "diverged"});
  return report;
}

StaggeringReport adaptive_study(const Problem& problem, const AdaptiveStudy& study) {
  const auto* coupled = problem.capability<SweepContraction>();
  const implicit::AdaptiveSettings& s = study.settings;
  const double t0 = problem.initial_time();
  const State initial = problem.initial_state();
  const implicit::AdaptiveRun run = implicit::run_adaptive(problem, initial, t0, t0 + study.duration, study.first_step, s);
  const AdaptiveVerdict verdict =
      check_adaptive(problem, run, initial, study.duration, study.tolerance, study.error_control);
  const double error = verdict.error, limit = verdict.limit, tolerance = study.tolerance;

  StaggeringReport report;
  std::string& text = report.text;
  appendf(text, "%s: Zohdi's Algorithm 7.1, %s sweeps, K_d = %d, TOL = %g, p = %g, from dt = %g over %g s%s\n",
          problem.name().c_str(), implicit::sweep_name(s.sweep).c_str(), s.target_sweeps, tolerance, s.exponent,
          study.first_step, study.duration, study.error_control ? ", local error held below TOL dt/duration" : "");
  appendf(text, "  steps taken      %ld\n", run.accepted);
  appendf(text, "  steps rejected   %ld (staggering: tolerance not met in K_d sweeps) + %ld (local error)\n",
          run.rejected_staggering, run.rejected_error);
  appendf(text, "  total sweeps     %ld\n", run.sweeps);
  appendf(text, "  accepted steps   first %.6g, smallest %.6g, largest %.6g s", run.first_step, run.smallest_step,
          run.largest_step);
  if (coupled)
    appendf(text, "; convergence limit %s = %.6g: %s", coupled->step_limit_formula().c_str(), limit,
            verdict.below_limit ? "every accepted step below it" : "A STEP AT OR ABOVE IT WAS ACCEPTED");
  appendf(text, "\n");
  if (!std::isnan(error))
    appendf(text, "  error at the end %.3g relative to the closed form (%s 10 x TOL = %g)\n", error,
            !study.error_control ? "not controlled: --no-error-control; compare"
            : error <= 10.0 * tolerance ? "within"
                                        : "ABOVE",
            10.0 * tolerance);
  report.passed = verdict.passed();
  appendf(text, "%s\n", report.passed ? "PASSED" : "FAILED");

  report.result = {{"case", problem.name()}, {"mode", "adaptive"}, {"sweep", implicit::sweep_name(s.sweep)},
                   {"target_sweeps", s.target_sweeps}, {"tolerance", s.tolerance}, {"exponent", s.exponent},
                   {"error_control", study.error_control}, {"dt_start", study.first_step}, {"duration", study.duration},
                   {"steps_taken", run.accepted}, {"steps_rejected_staggering", run.rejected_staggering},
                   {"steps_rejected_error", run.rejected_error}, {"total_sweeps", run.sweeps},
                   {"first_step", run.first_step}, {"smallest_step", run.smallest_step}, {"largest_step", run.largest_step},
                   {"step_limit", coupled ? nlohmann::json(limit) : nlohmann::json()},
                   {"error_at_end", null_if_nan(error)},
                   {"passed", report.passed}};
  report.csv = csv_of(nlohmann::json::array({report.result}),
                      {"steps_taken", "steps_rejected_staggering", "steps_rejected_error", "total_sweeps", "first_step",
                       "smallest_step", "largest_step", "step_limit", "error_at_end", "passed"});
  return report;
}

}  // namespace dlpverify::thermal
