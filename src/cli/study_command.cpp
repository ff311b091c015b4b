#include "cli/study_command.hpp"

#include <iostream>
#include <optional>

#include <omp.h>

#include "cli/problems.hpp"
#include "dlpverify/reference.hpp"
#include "cli/setup.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/history.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study.hpp"
#include "sundials/integrators.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "dlpverify/errors.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

namespace {

// converge, and check when `check` is given (the same options, plus the expected order).
int run_study(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line) {
  CvodeSettings cvode = cvode_settings(options.cvode, options.solver);
  const int integrator_order = make_integrator(options.integrator, cvode)->order();  // validates the name
  StudySetup r = resolve_setup(options.problem, options.levels, options.reference, options.solver, output_files(options));
  r.plan.expected_order = check ? *check->expect_order : integrator_order;
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const Problem& problem = *r.problem;
  const State initial = problem.initial_state();
  const double t0 = problem.initial_time();
  if (options.cvode.atol) cvode.atol = absolute_tolerances(problem, initial, *options.cvode.atol);
  const auto integrator = make_integrator(options.integrator, cvode);

  StudyResult study;
  Reference reference;
  std::vector<HistoryPoint> history;
  try {
    reference = compute_reference(problem, r.reference, initial, r.plan.t_end, r.plan.variables);
    const Solve solve = [&](double dt, long steps, nlohmann::json& statistics) {
      State state = initial;
      integrator->advance(problem, state, t0, dt, steps);
      statistics = integrator->statistics();
      return problem.measured(state, r.plan.t_end);
    };
    const State measured_reference = problem.measured(reference.state, r.plan.t_end);
    study = run_study(r.plan, measured_reference, reference.error_estimate, solve);
    if (!options.history_file.empty()) {
      const LevelResult& finest = study.levels.back();
      const AdvanceSteps advance = [&](State& state, double tau_from, double dt, long steps) {
        integrator->advance(problem, state, t0 + tau_from, dt, steps);
      };
      const Measure measure = [&problem](const State& state, double tau) { return problem.measured(state, tau); };
      history = record_history(initial, r.plan.variables, finest.dt, finest.steps, options.history_outputs, advance,
                               reference_trajectory(problem, r.reference, initial), measure);
    }
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": " + e.what());
  }

  std::optional<CheckVerdict> verdict;
  if (check) verdict = check_orders(study, *check->expect_order, check->order_tolerance);

  StudyDescription description;
  description.case_name = problem.name();
  description.integrator = integrator->name();
  description.integrator_order = integrator->order();
  description.reference = reference.kind;
  description.reference_detail = reference.detail;
  description.reference_statistics = reference.statistics;
  description.particles = initial.rows();
  description.t0 = t0;
  description.options = check ? to_json(*check) : to_json(options);
  description.provenance = provenance(command_line);
  description.diagnostics = problem.diagnostics(initial, study.finest, r.plan.t_end);

  const std::string table = format_table(description, study, verdict);
  const nlohmann::json result = to_json(description, study, verdict);
  // The figure first: if gnuplot fails, no file has been written yet.
  const OutputOptions& out = options.outputs;
  if (!out.plot_file.empty())
    plot_convergence({result}, PlotOptions{out.plot_file, out.title, "--plot", options.plot_relative, {}});
  std::cout << table << std::flush;
  if (!out.json_file.empty()) write_file_atomically(out.json_file, json_text(result, 2) + "\n");
  if (!out.csv_file.empty()) write_file_atomically(out.csv_file, format_csv(description, study));
  if (!out.table_file.empty()) write_file_atomically(out.table_file, table);
  if (!options.history_file.empty())
    write_file_atomically(options.history_file, format_history(history, r.plan.variables));
  if (!options.per_particle_file.empty())
    write_file_atomically(options.per_particle_file,
                          format_per_particle(study, problem.measured(reference.state, r.plan.t_end), member_coordinate(problem)));
  return verdict && !verdict->passed ? kExitCheckFailed : kExitDone;
}

}  // namespace

int run_converge_command(ConvergeOptions options, const std::string& command_line) {
  validate(options);
  return run_study(options, nullptr, command_line);
}

int run_check_command(CheckOptions options, const std::string& command_line) {
  validate(options);
  return run_study(options, &options, command_line);
}

}  // namespace dlpverify::cli
