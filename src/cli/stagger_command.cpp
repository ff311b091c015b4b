#include "cli/stagger_command.hpp"

#include <cmath>
#include <cstdio>

#include "io/value_checks.hpp"
#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/splitting.hpp"
#include "integrators/implicit/adaptive.hpp"
#include "io/atomic_file.hpp"
#include "io/provenance.hpp"
#include "io/format.hpp"
#include "problems/thermal/staggering_study.hpp"
#include "case_study/inputs.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

namespace {

using implicit::Sweep;

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

// The outputs, together or not at all, then the text on the console (unless an output took it).
void finish(const StaggerOptions& o, const thermal::StaggeringReport& report, const std::string& command_line) {
  nlohmann::json result = report.result;
  result["provenance"] = provenance(command_line);
  result["options"] = problem_options_json(o.problem);
  OutputSet outputs;
  if (wanted(o.json_file)) outputs.add(o.json_file, json_text(result, 2) + "\n");
  if (wanted(o.csv_file)) outputs.add(o.csv_file, report.csv);
  if (wanted(o.table_file)) outputs.add(o.table_file, report.text);
  outputs.commit();
  if (!any_on_standard_output({{"--json", o.json_file}, {"--csv", o.csv_file}, {"--table", o.table_file}}))
    std::fputs(console_text(report.text).c_str(), stdout);
}

int contraction(const StaggerOptions& o, const Problem& problem, const std::string& command_line) {
  const thermal::StaggeringReport report = thermal::contraction_study(problem, sweep_of(o), o.dt);
  // No JSON: a failed run writes no results.
  if (report.failed_step)
    throw SolverError("stagger: at --dt " + printf_string("%g", *report.failed_step) + " " + report.failure);
  finish(o, report, command_line);
  return kExitDone;
}

int adaptive(const StaggerOptions& o, const Problem& problem, const std::string& command_line) {
  const auto* coupled = problem.capability<SweepContraction>();
  thermal::AdaptiveStudy study;
  implicit::AdaptiveSettings& s = study.settings;
  s.sweep = sweep_of(o);
  s.target_sweeps = o.target_sweeps;
  s.tolerance = block_tolerances(o, staggered_blocks(problem));
  s.exponent = o.exponent ? *o.exponent : coupled ? coupled->radius_exponent() : 1.0;
  if (o.dt_max) s.dt_max = *o.dt_max;
  if (!o.no_error_control) s.error_tolerance = o.tolerance;
  study.first_step = o.dt[0];
  study.duration = o.t_end ? *o.t_end : find_case_entry(o.problem.case_name).defaults.t_end;
  study.tolerance = o.tolerance;
  study.error_control = !o.no_error_control;
  const thermal::StaggeringReport report = thermal::adaptive_study(problem, study);
  finish(o, report, command_line);
  return report.passed ? kExitDone : kExitCheckFailed;
}

}  // namespace

CLI::App* add_stagger_command(CLI::App& parent, StaggerOptions& o) {
  CLI::App& app = *parent.add_subcommand(
      "stagger", "Staggered backward Euler: measured contraction against the spectral radius per --dt, or Zohdi's "
                 "adaptive Algorithm 7.1 (--adaptive) with its Table 7.1 counts (docs/model.md §7.3)");
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
  return &app;
}

int run_stagger_command(StaggerOptions& o, const std::string& command_line) {
  validate(o);
  fill_case_defaults(o.problem);
  const std::unique_ptr<Problem> problem = make_problem(o.problem);
  if (!o.adaptive) return contraction(o, *problem, command_line);
  return adaptive(o, *problem, command_line);
}

}  // namespace dlpverify::cli
