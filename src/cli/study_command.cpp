#include "cli/study_command.hpp"

#include <iostream>
#include <optional>

#include <omp.h>

#include "problems/dlp/case.hpp"
#include "sundials/reference.hpp"
#include "cli/setup.hpp"
#include "harness/check.hpp"
#include "harness/history.hpp"
#include "harness/report.hpp"
#include "harness/study.hpp"
#include "integrators/registry.hpp"
#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

namespace {

CvodeSettings cvode_settings(const Options& o) {
  CvodeSettings s;
  s.rtol = o.rtol;
  s.method = o.method == "bdf" ? CvodeMethod::bdf : CvodeMethod::adams;
  s.linear_solver = o.linear_solver == "spgmr" ? CvodeLinearSolver::spgmr : CvodeLinearSolver::diagonal;
  s.max_steps = o.max_steps;
  s.openmp_vector = o.vector == "openmp";
  return s;
}

}  // namespace

int run_study_command(Options options, bool check, const std::string& command_line) {
  CvodeSettings cvode = cvode_settings(options);
  const int integrator_order = make_integrator(options.integrator, cvode)->order();  // validates the name
  StudySetup r = resolve_setup(options, check ? Command::check : Command::converge);
  r.plan.expected_order = options.expect_order ? *options.expect_order : integrator_order;
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const Cloud initial = make_cloud(r.lattice, r.launch, r.physics.parameters);
  const double t0 = initial_time(r.lattice, r.launch);
  if (options.atol) cvode.atol = absolute_tolerances(initial, *options.atol);
  const auto integrator = make_integrator(options.integrator, cvode);
  const ParticleRates rates(r.physics);

  StudyResult study;
  Reference reference;
  std::vector<HistoryPoint> history;
  try {
    reference = compute_reference(*r.test_case, r.reference, r.physics, initial, t0, r.plan.t_end, r.plan.variables);
    const Solve solve = [&](double dt, long steps, nlohmann::json& statistics) {
      Cloud state = initial;
      integrator->advance(rates, state, t0, dt, steps);
      statistics = integrator->statistics();
      return state;
    };
    study = run_study(r.plan, reference.state, reference.error_estimate, solve);
    if (!options.history_file.empty()) {
      const LevelResult& finest = study.levels.back();
      const AdvanceSteps advance = [&](Cloud& state, double tau_from, double dt, long steps) {
        integrator->advance(rates, state, t0 + tau_from, dt, steps);
      };
      history = record_history(initial, r.plan.variables, finest.dt, finest.steps, options.history_outputs, advance,
                               reference_trajectory(*r.test_case, r.reference, r.physics, initial, t0));
    }
  } catch (const SolverError& e) {
    throw SolverError("case " + r.test_case->name + ": " + e.what());
  }

  std::optional<CheckVerdict> verdict;
  if (check) verdict = check_orders(study, *options.expect_order, options.order_tolerance);

  StudyDescription description;
  description.case_name = r.test_case->name;
  description.integrator = integrator->name();
  description.integrator_order = integrator->order();
  description.reference = reference.kind;
  description.reference_detail = reference.detail;
  description.reference_statistics = reference.statistics;
  description.particles = initial.size();
  description.t0 = t0;
  description.options = to_json(options);
  description.provenance = provenance(command_line);
  if (r.test_case->diagnostics)
    description.diagnostics = r.test_case->diagnostics({r.physics, r.launch, initial, study.finest, r.plan.t_end});

  const std::string table = format_table(description, study, verdict);
  const nlohmann::json result = to_json(description, study, verdict);
  // The figure first: if gnuplot fails, no file has been written yet.
  if (!options.plot_file.empty())
    plot_convergence({result}, PlotOptions{options.plot_file, options.title, "--plot", options.plot_relative, {}});
  std::cout << table << std::flush;
  if (!options.json_file.empty()) write_file_atomically(options.json_file, result.dump(2) + "\n");
  if (!options.csv_file.empty()) write_file_atomically(options.csv_file, format_csv(description, study));
  if (!options.table_file.empty()) write_file_atomically(options.table_file, table);
  if (!options.history_file.empty())
    write_file_atomically(options.history_file, format_history(history, r.plan.variables));
  if (!options.per_particle_file.empty())
    write_file_atomically(options.per_particle_file,
                          format_per_particle(study, reference.state, similarity_coordinate(initial, t0, r.launch)));
  return verdict && !verdict->passed ? kExitCheckFailed : kExitDone;
}

}  // namespace dlpverify::cli
