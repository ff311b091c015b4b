#include "cli/study_command.hpp"

#include <iostream>
#include <optional>

#include <omp.h>

#include "cases/case.hpp"
#include "convergence/check.hpp"
#include "convergence/report.hpp"
#include "convergence/study.hpp"
#include "exact/cloud_solution.hpp"
#include "integrators/registry.hpp"
#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/provenance.hpp"

namespace dlpverify::cli {

namespace {

// Everything a study needs, resolved and validated before any work or output.
struct ResolvedStudy {
  const Case* test_case = nullptr;
  Physics physics;
  Lattice lattice;
  Launch launch;
  StudyPlan plan;
  std::unique_ptr<Integrator> integrator;
};

ResolvedStudy resolve(Options& o, bool check) {
  validate(o, check);
  ResolvedStudy r;
  r.test_case = &find_case(o.case_name);
  r.integrator = make_integrator(o.integrator);

  // Fill the case's defaults into the options so the report shows what was actually run.
  const CaseDefaults& defaults = r.test_case->defaults;
  if (!o.t_end) o.t_end = defaults.t_end;
  if (!o.dt) o.dt = defaults.dt;
  if (!o.levels) o.levels = defaults.levels;
  r.lattice.shape = o.shape == "sphere" ? Shape::sphere : Shape::shell;
  r.lattice.outer = o.outer;
  if (!o.inner) o.inner = Lattice::default_inner(r.lattice.shape, o.outer);
  r.lattice.inner = *o.inner;
  if (!o.spacing) o.spacing = o.parameters.diameter;
  r.lattice.spacing = *o.spacing;
  r.launch.expansion_speed = o.expansion_speed;

  r.physics.parameters = o.parameters;
  r.physics.terms = r.test_case->terms;

  r.plan.t_end = *o.t_end;
  r.plan.coarsest_dt = *o.dt;
  r.plan.ratio = o.ratio;
  r.plan.levels = *o.levels;
  r.plan.expected_order = o.expect_order ? *o.expect_order : r.integrator->order();
  r.plan.variables = measured_variables(r.physics.terms);
  level_steps(r.plan);  // throws when a level's step count is not whole

  if (!o.json_file.empty()) check_output_path("--json", o.json_file);
  if (!o.csv_file.empty()) check_output_path("--csv", o.csv_file);
  if (!o.table_file.empty()) check_output_path("--table", o.table_file);
  return r;
}

}  // namespace

int run_study_command(Options options, bool check, const std::string& command_line) {
  ResolvedStudy r = resolve(options, check);
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const Cloud initial = make_cloud(r.lattice, r.launch, r.physics.parameters);
  const double t0 = initial_time(r.lattice, r.launch);
  const Cloud reference = exact::evaluate(r.test_case->solution, r.physics, initial, r.plan.t_end);
  const ParticleRates rates(r.physics);

  const Solve solve = [&](double dt, long steps, nlohmann::json& statistics) {
    Cloud state = initial;
    r.integrator->advance(rates, state, t0, dt, steps);
    statistics = r.integrator->statistics();
    return state;
  };
  const StudyResult study = run_study(r.plan, reference, solve);

  std::optional<CheckVerdict> verdict;
  if (check) verdict = check_orders(study, *options.expect_order, options.order_tolerance);

  StudyDescription description;
  description.case_name = r.test_case->name;
  description.integrator = r.integrator->name();
  description.integrator_order = r.integrator->order();
  description.reference = "exact";
  description.reference_detail = r.test_case->reference_detail;
  description.particles = initial.size();
  description.t0 = t0;
  description.options = to_json(options);
  description.provenance = provenance(command_line);

  const std::string table = format_table(description, study, verdict);
  std::cout << table << std::flush;
  if (!options.json_file.empty())
    write_file_atomically(options.json_file, to_json(description, study, verdict).dump(2) + "\n");
  if (!options.csv_file.empty()) write_file_atomically(options.csv_file, format_csv(description, study));
  if (!options.table_file.empty()) write_file_atomically(options.table_file, table);
  return verdict && !verdict->passed ? kExitCheckFailed : kExitDone;
}

}  // namespace dlpverify::cli
