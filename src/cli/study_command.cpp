#include "cli/study_command.hpp"

#include <cstdio>
#include <iostream>
#include <optional>

#include <omp.h>

#include "audit/baseline_audit.hpp"
#include "cases/case.hpp"
#include "cases/reference.hpp"
#include "convergence/check.hpp"
#include "convergence/history.hpp"
#include "convergence/report.hpp"
#include "convergence/study.hpp"
#include "exact/burn.hpp"
#include "integrators/registry.hpp"
#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

namespace {

// Everything a study needs, resolved and validated before any work or output.
struct ResolvedStudy {
  const Case* test_case = nullptr;
  Physics physics;
  Lattice lattice;
  Launch launch;
  StudyPlan plan;
  CvodeSettings cvode;  // for --integrator cvode; atol is filled in from the launch cloud
  ReferenceSettings reference;
  int integrator_order = 0;
};

CvodeSettings cvode_settings(const Options& o) {
  CvodeSettings s;
  s.rtol = o.rtol;
  s.method = o.method == "bdf" ? CvodeMethod::bdf : CvodeMethod::adams;
  s.linear_solver = o.linear_solver == "spgmr" ? CvodeLinearSolver::spgmr : CvodeLinearSolver::diagonal;
  s.max_steps = o.max_steps;
  s.openmp_vector = o.vector == "openmp";
  return s;
}

ResolvedStudy resolve(Options& o, bool check) {
  validate(o, check);
  ResolvedStudy r;
  r.test_case = &find_case(o.case_name);
  r.cvode = cvode_settings(o);
  r.integrator_order = make_integrator(o.integrator, r.cvode)->order();  // validates the name

  // Fill the case's defaults into the options so the report shows what was actually run.
  const CaseDefaults& defaults = r.test_case->defaults;
  if (!o.t_end) o.t_end = defaults.t_end;
  if (!o.dt) o.dt = defaults.dt;
  if (!o.levels) o.levels = defaults.levels;
  if (!o.reference) o.reference = r.test_case->solution ? "exact" : "cvode";
  r.lattice.shape = o.shape == "sphere" ? Shape::sphere : Shape::shell;
  r.lattice.outer = o.outer;
  if (!o.inner) o.inner = Lattice::default_inner(r.lattice.shape, o.outer);
  r.lattice.inner = *o.inner;
  if (!o.spacing) o.spacing = o.parameters.diameter;
  r.lattice.spacing = *o.spacing;
  r.launch.expansion_speed = o.expansion_speed;
  r.lattice.z_axis_only = r.test_case->z_axis_only;

  r.physics.parameters = o.parameters;
  r.physics.terms = r.test_case->terms;

  r.reference.kind = *o.reference == "exact" ? ReferenceKind::exact : ReferenceKind::cvode;
  if (r.reference.kind == ReferenceKind::exact && !r.test_case->solution)
    throw InputError("--reference", "exact", "case " + r.test_case->name + " has no closed form; use cvode");
  r.reference.rtol = o.reference_rtol;
  r.reference.max_steps = o.max_steps;  // bounds every CVODE solve, the reference's too
  r.reference.openmp_vector = o.vector == "openmp";

  r.plan.t_end = *o.t_end;
  r.plan.coarsest_dt = *o.dt;
  r.plan.ratio = o.ratio;
  r.plan.levels = *o.levels;
  r.plan.expected_order = o.expect_order ? *o.expect_order : r.integrator_order;
  r.plan.variables = measured_variables(r.physics.terms);
  level_steps(r.plan);  // throws when a level's step count is not whole
  if (r.physics.terms.burning) exact::check_before_burn_out(r.physics.parameters, r.plan.t_end);

  if (!o.json_file.empty()) check_output_path("--json", o.json_file);
  if (!o.csv_file.empty()) check_output_path("--csv", o.csv_file);
  if (!o.table_file.empty()) check_output_path("--table", o.table_file);
  if (!o.per_particle_file.empty()) check_output_path("--per-particle", o.per_particle_file);
  if (!o.history_file.empty()) check_output_path("--history", o.history_file);
  if (!o.plot_file.empty()) check_plot_path("--plot", o.plot_file);

  // SPEC §4: a closed form is trusted only after its audit passes, on this study's physics.
  if (r.reference.kind == ReferenceKind::exact) {
    const BaselineAudit audit = audit_case(*r.test_case, r.physics, r.plan.t_end);
    if (!audit.passed) {
      char why[256];
      std::snprintf(why, sizeof why,
                    "its closed form failed the audit (ODE residual %.2e, CVODE distance %.2e, %d non-finite; "
                    "limits 1e-8, 1e-9): refusing it as a reference (see dlpverify audit)",
                    audit.residual, audit.cvode_distance, audit.non_finite);
      throw InputError("--case", r.test_case->name, why);
    }
  }
  return r;
}

}  // namespace

int run_study_command(Options options, bool check, const std::string& command_line) {
  ResolvedStudy r = resolve(options, check);
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const Cloud initial = make_cloud(r.lattice, r.launch, r.physics.parameters);
  const double t0 = initial_time(r.lattice, r.launch);
  if (options.atol) r.cvode.atol = absolute_tolerances(initial, *options.atol);
  const auto integrator = make_integrator(options.integrator, r.cvode);
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
