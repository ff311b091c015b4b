#include "cli/stagger_command.hpp"

#include <cmath>
#include <cstdarg>
#include <algorithm>
#include <cstdio>

#include "cli/option_checks.hpp"
#include "cli/problems.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/splitting.hpp"
#include "integrators/implicit/adaptive.hpp"
#include "integrators/implicit/member_norms.hpp"
#include "integrators/implicit/staggered_solver.hpp"
#include "io/atomic_file.hpp"
#include "io/provenance.hpp"
#include "problems/thermal/adaptive_check.hpp"
#include "dlpverify/splitting.hpp"
#include "cli/study_inputs.hpp"

namespace dlpverify::cli {

namespace {

using implicit::Sweep;

constexpr double kStepTolerance = 1e-14;  // contraction mode: sweep to round-off
constexpr int kStepSweeps = 1000;

Sweep sweep_of(const StaggerOptions& o) {
  if (o.sweep.empty()) return o.adaptive ? Sweep::gauss_seidel : Sweep::jacobi;
  return o.sweep == "jacobi" ? Sweep::jacobi : Sweep::gauss_seidel;
}

void validate(const StaggerOptions& o) {
  validate_problem_options(o.problem);
  if (o.dt.empty()) throw InputError("--dt", "", "give at least one step");
  for (double dt : o.dt) require_positive("--dt", dt);
  if (o.adaptive && o.dt.size() != 1) throw InputError("--dt", value_text(o.dt[1]), "--adaptive takes one first step");
  if (!o.sweep.empty() && o.sweep != "jacobi" && o.sweep != "gauss-seidel")
    throw InputError("--sweep", o.sweep, "must be jacobi or gauss-seidel");
  if (o.t_end) require_positive("--t-end", *o.t_end);
  if (!(o.tolerance >= 1e-14 && o.tolerance < 1.0)) throw InputError("--tol", value_text(o.tolerance), "must lie in [1e-14, 1)");
  if (o.target_sweeps < 2 || o.target_sweeps > 1000)
    throw InputError("--target-sweeps", std::to_string(o.target_sweeps), "must lie in [2, 1000]");
  if (o.exponent) require_positive("--exponent", *o.exponent);
  if (o.dt_max) require_positive("--dt-max", *o.dt_max);
  const std::vector<std::pair<std::string, std::string>> outputs{
      {"--json", o.json_file}, {"--csv", o.csv_file}, {"--table", o.table_file}};
  validate_outputs(outputs, "");
  refuse_shared_files({}, named_paths(outputs));
  for (const auto& [option, path] : outputs)
    if (!path.empty()) check_output_path(option, path);
}

// TOL per block: --tol, then each BLOCK=TOL of --block-tol.
std::vector<double> block_tolerances(const StaggerOptions& o, const std::vector<FieldBlock>& blocks) {
  std::vector<double> tolerance(blocks.size(), o.tolerance);
  for (const std::string& item : o.block_tolerances) {
    const std::size_t eq = item.find('=');
    std::size_t b = 0;
    while (eq != std::string::npos && b < blocks.size() && blocks[b].name != item.substr(0, eq)) ++b;
    if (eq == std::string::npos || b == blocks.size())
      throw InputError("--block-tol", item, "must be BLOCK=TOL with BLOCK one of the case's blocks (" + blocks.front().name + ", …)");
    std::size_t used = 0;
    double value = std::nan("");
    try {
      value = std::stod(item.substr(eq + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() - eq - 1 || !(value >= 1e-14 && value < 1.0))
      throw InputError("--block-tol", item, "its tolerance must lie in [1e-14, 1)");
    tolerance[b] = value;
  }
  return tolerance;
}

// printf into a text the command prints (or writes with --table) when it is done.
[[gnu::format(printf, 2, 3)]] void appendf(std::string& text, const char* format, ...) {
  char buffer[600];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  text += buffer;
}

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

// The outputs, together or not at all, then the text on the console (unless an output took it).
void finish(const StaggerOptions& o, const std::string& text, nlohmann::json result, const std::string& csv,
            const std::string& command_line) {
  result["provenance"] = provenance(command_line);
  result["options"] = problem_options_json(o.problem);
  OutputSet outputs;
  if (wanted(o.json_file)) outputs.add(o.json_file, json_text(result, 2) + "\n");
  if (wanted(o.csv_file)) outputs.add(o.csv_file, csv);
  if (wanted(o.table_file)) outputs.add(o.table_file, text);
  outputs.commit();
  if (!any_on_standard_output({{"--json", o.json_file}, {"--csv", o.csv_file}, {"--table", o.table_file}}))
    std::fputs(text.c_str(), stdout);
}

int contraction(const StaggerOptions& o, const Problem& problem, const std::string& command_line) {
  const Sweep sweep = sweep_of(o);
  const auto* coupled = problem.capability<SweepContraction>();
  const State y = problem.initial_state();
  implicit::StaggeredSolver solver(problem, sweep, y);
  const std::vector<double> tolerance(solver.blocks().size(), kStepTolerance);
  std::string text;
  appendf(text, "%s: one backward-Euler step from the initial state, %s sweeps (contraction over %d sweeps)\n",
              problem.name().c_str(), implicit::sweep_name(sweep).c_str(), solver.window());
  appendf(text, "%12s %7s %16s %16s %12s\n", "dt", "sweeps", "contraction", "spectral radius", "rel. diff.");
  nlohmann::json rows = nlohmann::json::array();
  std::string divergence;
  State w;
  for (double dt : o.dt) {
    const implicit::StaggeredIteration it = solver.step(y, problem.initial_time(), dt, tolerance, kStepSweeps, w);
    const double radius = coupled ? (sweep == Sweep::jacobi ? coupled->jacobi_radius(dt) : coupled->gauss_seidel_radius(dt))
                                  : std::nan("");
    const double difference = std::abs(it.contraction - radius) / radius;
    // "-": too few sweeps to measure (converged within W + 1), or no known radius for this case
    const auto number = [](double x, const char* format) {
      char cell[32];
      std::snprintf(cell, sizeof cell, format, x);
      return std::isnan(x) ? std::string("-") : std::string(cell);
    };
    appendf(text, "%12.6g %7d %16s %16s %12s  %s\n", dt, it.sweeps, number(it.contraction, "%.10f").c_str(),
            number(radius, "%.10f").c_str(), number(difference, "%.3g").c_str(),
            it.converged ? "converged" : it.diverged ? "DIVERGES" : "not converged");
    const auto json_number = [](double x) { return std::isnan(x) ? nlohmann::json() : nlohmann::json(x); };
    rows.push_back({{"dt", dt}, {"sweeps", it.sweeps}, {"contraction", json_number(it.contraction)},
                    {"spectral_radius", coupled ? nlohmann::json(radius) : nlohmann::json()},
                    {"converged", it.converged}, {"diverged", it.diverged}});
    if (!it.converged && divergence.empty()) {
      char line[400];
      std::snprintf(line, sizeof line,
                    "stagger: at --dt %g the staggered iteration %s after %d sweeps: measured contraction %.6g per "
                    "sweep%s",
                    dt, it.diverged ? "diverges" : "does not converge", it.sweeps, it.contraction,
                    coupled ? (", spectral radius " + (sweep == Sweep::jacobi ? coupled->jacobi_radius_formula() : coupled->gauss_seidel_radius_formula()) + " = " + value_text(radius) +
                               "; it converges only for dt < " + value_text(coupled->step_limit()))
                                  .c_str()
                            : "");
      divergence = line;
    }
  }
  if (!divergence.empty()) throw SolverError(divergence);  // no JSON: a failed run writes no results
  finish(o, text,
         {{"case", problem.name()}, {"mode", "contraction"}, {"sweep", implicit::sweep_name(sweep)},
          {"window", solver.window()}, {"rows", rows}},
         csv_of(rows, {"dt", "sweeps", "contraction", "spectral_radius", "converged", "diverged"}), command_line);
  return kExitDone;
}


int adaptive(const StaggerOptions& o, const Problem& problem, const std::string& command_line) {
  const auto* coupled = problem.capability<SweepContraction>();
  const double t0 = problem.initial_time();
  const double duration = o.t_end ? *o.t_end : find_case_entry(o.problem.case_name).defaults.t_end;
  implicit::AdaptiveSettings s;
  s.sweep = sweep_of(o);
  s.target_sweeps = o.target_sweeps;
  s.tolerance = block_tolerances(o, staggered_blocks(problem));
  s.exponent = o.exponent ? *o.exponent : coupled ? coupled->radius_exponent() : 1.0;
  if (o.dt_max) s.dt_max = *o.dt_max;
  if (!o.no_error_control) s.error_tolerance = o.tolerance;
  const State initial = problem.initial_state();
  const implicit::AdaptiveRun run = implicit::run_adaptive(problem, initial, t0, t0 + duration, o.dt[0], s);

  const thermal::AdaptiveVerdict verdict = thermal::check_adaptive(problem, run, initial, duration, o.tolerance,
                                                                  !o.no_error_control);
  const double error = verdict.error, limit = verdict.limit;
  const bool below_limit = verdict.below_limit, accurate = verdict.accurate;
  std::string text;

  appendf(text, "%s: Zohdi's Algorithm 7.1, %s sweeps, K_d = %d, TOL = %g, p = %g, from dt = %g over %g s%s\n",
              problem.name().c_str(), implicit::sweep_name(s.sweep).c_str(), s.target_sweeps, o.tolerance, s.exponent,
              o.dt[0], duration, o.no_error_control ? "" : ", local error held below TOL dt/duration");
  appendf(text, "  steps taken      %ld\n", run.accepted);
  appendf(text, "  steps rejected   %ld (staggering: tolerance not met in K_d sweeps) + %ld (local error)\n",
              run.rejected_staggering, run.rejected_error);
  appendf(text, "  total sweeps     %ld\n", run.sweeps);
  appendf(text, "  accepted steps   first %.6g, smallest %.6g, largest %.6g s", run.first_step, run.smallest_step,
              run.largest_step);
  if (coupled)
    appendf(text, "; convergence limit %s = %.6g: %s", coupled->step_limit_formula().c_str(), limit,
                below_limit ? "every accepted step below it" : "A STEP AT OR ABOVE IT WAS ACCEPTED");
  appendf(text, "\n");
  if (!std::isnan(error))
    appendf(text, "  error at the end %.3g relative to the closed form (%s 10 x TOL = %g)\n", error,
                o.no_error_control ? "not controlled: --no-error-control; compare"
                                   : error <= 10.0 * o.tolerance ? "within" : "ABOVE",
                10.0 * o.tolerance);
  appendf(text, "%s\n", below_limit && accurate ? "PASSED" : "FAILED");

  const nlohmann::json result{{"case", problem.name()}, {"mode", "adaptive"}, {"sweep", implicit::sweep_name(s.sweep)},
              {"target_sweeps", s.target_sweeps}, {"tolerance", s.tolerance}, {"exponent", s.exponent},
              {"error_control", !o.no_error_control}, {"dt_start", o.dt[0]}, {"duration", duration},
              {"steps_taken", run.accepted}, {"steps_rejected_staggering", run.rejected_staggering},
              {"steps_rejected_error", run.rejected_error}, {"total_sweeps", run.sweeps},
              {"first_step", run.first_step}, {"smallest_step", run.smallest_step}, {"largest_step", run.largest_step},
              {"step_limit", coupled ? nlohmann::json(limit) : nlohmann::json()},
              {"error_at_end", std::isnan(error) ? nlohmann::json() : nlohmann::json(error)},
              {"passed", below_limit && accurate}};
  finish(o, text, result,
         csv_of(nlohmann::json::array({result}),
                {"steps_taken", "steps_rejected_staggering", "steps_rejected_error", "total_sweeps", "first_step",
                 "smallest_step", "largest_step", "step_limit", "error_at_end", "passed"}),
         command_line);
  return below_limit && accurate ? kExitDone : kExitCheckFailed;
}

}  // namespace

void add_options(CLI::App& app, StaggerOptions& o) {
  app.add_option("--case", o.problem.case_name, "Case (any; the spectral radius is known for stagger-2x2 and stagger-3x3)")
      ->capture_default_str();
  add_problem_options(app, o.problem);
  const std::string group = "Staggering (docs/model.md §7.3)";
  app.add_option("--dt", o.dt, "Steps (comma-separated); with --adaptive, the first step")
      ->required()->delimiter(',')->group(group);
  app.add_option("--sweep", o.sweep, "jacobi | gauss-seidel [default: jacobi; --adaptive: gauss-seidel]")->group(group);
  app.add_flag("--adaptive", o.adaptive, "Run Zohdi's Algorithm 7.1 from --dt to --t-end")->group(group);
  app.add_option("--t-end", o.t_end, "Duration of the adaptive run [s] [default: the case's]")->group(group);
  app.add_option("--tol", o.tolerance, "TOL of every block, and the local-error tolerance")->capture_default_str()->group(group);
  app.add_option("--block-tol", o.block_tolerances, "BLOCK=TOL: one block's own TOL (repeatable)")->group(group);
  app.add_option("--target-sweeps", o.target_sweeps, "K_d: the sweeps a step aims at")->capture_default_str()->group(group);
  app.add_option("--exponent", o.exponent, "p of rho ~ dt^p [default: the system's (1, 4/3), else 1]")->group(group);
  app.add_option("--dt-max", o.dt_max, "Upper bound dt_lim on the step [s] [default: none]")->group(group);
  app.add_flag("--no-error-control", o.no_error_control, "Zohdi's control alone: no local-error bound on dt")->group(group);
  const std::string outputs = "Outputs (each written whole, or not at all)";
  app.add_option("--json", o.json_file, "Write the result as JSON")->group(outputs);
  app.add_option("--csv", o.csv_file, "Write the rows (contraction) or the counts (--adaptive) as CSV")->group(outputs);
  app.add_option("--table", o.table_file, "Write the console table to a file instead of the console")->group(outputs);
}

int run_stagger_command(StaggerOptions& o, const std::string& command_line) {
  validate(o);
  fill_case_defaults(o.problem);
  const std::unique_ptr<Problem> problem = make_problem(o.problem);
  if (!o.adaptive) return contraction(o, *problem, command_line);
  return adaptive(o, *problem, command_line);
}

}  // namespace dlpverify::cli
