#include "cli/precision_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>

#include <omp.h>

#include "cases/case.hpp"
#include "cases/reference.hpp"
#include "convergence/study.hpp"
#include "convergence/work_precision.hpp"
#include "integrators/registry.hpp"
#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

namespace {

std::string text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// Everything the study needs, resolved and validated before any work or output.
struct ResolvedPrecision {
  const Case* test_case = nullptr;
  Physics physics;
  Lattice lattice;
  Launch launch;
  StudyPlan plan;              // the fixed-step levels and the measured variables
  std::vector<double> rtols;   // CVODE's sweep
  CvodeSettings cvode;         // rtol, atol and method are set per run
  ReferenceSettings reference;
};

ResolvedPrecision resolve(Options& o) {
  validate(o, Command::precision);
  ResolvedPrecision r;
  r.test_case = &find_case(o.case_name);
  // The fixed-step method beside CVODE: CVODE is already swept, by tolerance.
  if (o.integrator == "cvode")
    throw InputError("--integrator", o.integrator,
                     "precision sweeps CVODE itself (adams and bdf); name a fixed-step method: rk2, euler, heun, rk4 "
                     "or arkode-erk:TABLE");
  if (make_integrator(o.integrator)->order() <= 0)  // validates the name too
    throw InputError("--integrator", o.integrator, "is not a fixed-step method");

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

  r.physics.parameters = o.parameters;
  r.physics.terms = r.test_case->terms;

  r.rtols = tolerance_sweep(o.rtol_max, o.rtol_min, o.per_decade);
  r.reference.kind = *o.reference == "exact" ? ReferenceKind::exact : ReferenceKind::cvode;
  if (r.reference.kind == ReferenceKind::exact && !r.test_case->solution)
    throw InputError("--reference", "exact", "case " + r.test_case->name + " has no closed form; use cvode");
  // A CVODE reference at the sweep's own tolerance would measure the tightest runs against
  // themselves (Adams reproduces its own result bit for bit): keep it a decade below at least.
  if (r.reference.kind == ReferenceKind::cvode && o.reference_rtol > r.rtols.back() / 10.0 * (1.0 + 1e-9))
    throw InputError("--reference-rtol", text(o.reference_rtol),
                     "must be at most the tightest rtol / 10 = " + text(r.rtols.back() / 10.0) +
                         ", or the tightest runs measure the reference against itself");
  r.reference.rtol = o.reference_rtol;
  r.reference.openmp_vector = o.vector == "openmp";

  r.cvode.linear_solver = o.linear_solver == "spgmr" ? CvodeLinearSolver::spgmr : CvodeLinearSolver::diagonal;
  r.cvode.max_steps = o.max_steps;
  r.cvode.openmp_vector = o.vector == "openmp";

  r.plan.t_end = *o.t_end;
  r.plan.coarsest_dt = *o.dt;
  r.plan.ratio = o.ratio;
  r.plan.levels = *o.levels;
  r.plan.variables = measured_variables(r.physics.terms);
  level_steps(r.plan);  // throws when a level's step count is not whole

  if (!o.json_file.empty()) check_output_path("--json", o.json_file);
  if (!o.csv_file.empty()) check_output_path("--csv", o.csv_file);
  if (!o.table_file.empty()) check_output_path("--table", o.table_file);
  if (!o.plot_file.empty()) check_plot_path("--plot", o.plot_file);
  return r;
}

// CVODE Adams and BDF over the sweep, then the fixed-step method at each level. Every run starts
// from a copy of `initial` with a fresh integrator, so none inherits another's state.
std::vector<PrecisionRun> make_runs(const ResolvedPrecision& r, const std::string& fixed_step, const Cloud& initial,
                                    const ParticleRates& rates, double t0) {
  const double t_end = r.plan.t_end;
  std::vector<PrecisionRun> runs;
  for (const CvodeMethod method : {CvodeMethod::adams, CvodeMethod::bdf}) {
    for (const double rtol : r.rtols) {
      CvodeSettings settings = r.cvode;
      settings.method = method;
      settings.rtol = rtol;
      settings.atol = absolute_tolerances(initial, rtol);
      const auto solve = [settings, &initial, &rates, t0, t_end](nlohmann::json& statistics) {
        CvodeIntegrator integrator(settings);
        Cloud state = initial;
        integrator.advance(rates, state, t0, t_end, 1);  // one "step" of t_end: no step limit but t_end
        statistics = integrator.statistics();
        return state;
      };
      runs.push_back({method == CvodeMethod::adams ? "adams" : "bdf", rtol, std::nullopt, solve});
    }
  }
  for (const long steps : level_steps(r.plan)) {
    const double dt = t_end / static_cast<double>(steps);  // lands on t_end whatever the ratio
    const auto solve = [fixed_step, &initial, &rates, t0, dt, steps](nlohmann::json& statistics) {
      const std::unique_ptr<Integrator> integrator = make_integrator(fixed_step);
      Cloud state = initial;
      integrator->advance(rates, state, t0, dt, steps);
      statistics = integrator->statistics();
      return state;
    };
    runs.push_back({fixed_step, std::nullopt, dt, solve});
  }
  return runs;
}

}  // namespace

int run_precision_command(Options options, const std::string& command_line) {
  const ResolvedPrecision r = resolve(options);
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const Cloud initial = make_cloud(r.lattice, r.launch, r.physics.parameters);
  const double t0 = initial_time(r.lattice, r.launch);
  const ParticleRates rates(r.physics);

  Reference reference;
  try {
    reference = compute_reference(*r.test_case, r.reference, r.physics, initial, t0, r.plan.t_end, r.plan.variables);
  } catch (const SolverError& e) {
    throw SolverError("case " + r.test_case->name + ": reference: " + e.what());
  }
  WorkPrecisionResult result;
  try {
    result = run_work_precision(make_runs(r, options.integrator, initial, rates, t0), reference.state,
                                reference.error_estimate, r.plan.variables);
  } catch (const SolverError& e) {
    throw SolverError("case " + r.test_case->name + ": " + e.what());
  }

  WorkPrecisionDescription description;
  description.case_name = r.test_case->name;
  description.reference = reference.kind;
  description.reference_detail = reference.detail;
  description.reference_statistics = reference.statistics;
  description.particles = initial.size();
  description.t0 = t0;
  description.t_end = r.plan.t_end;
  description.options = to_json(options, Command::precision);
  description.provenance = provenance(command_line);

  const std::string table = format_table(description, result);
  const nlohmann::json json = to_json(description, result);
  // The figure first: if gnuplot fails, no file has been written yet.
  if (!options.plot_file.empty())
    plot_work_precision({json}, PlotOptions{options.plot_file, options.title, "--plot", false, {}});
  std::cout << table << std::flush;
  if (!options.json_file.empty()) write_file_atomically(options.json_file, json.dump(2) + "\n");
  if (!options.csv_file.empty()) write_file_atomically(options.csv_file, format_csv(description, result));
  if (!options.table_file.empty()) write_file_atomically(options.table_file, table);
  return kExitDone;
}

}  // namespace dlpverify::cli
