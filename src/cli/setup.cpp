#include "cli/setup.hpp"

#include <cstdio>

#include "sundials/baseline_audit.hpp"
#include "problems/dlp/exact/burn.hpp"
#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

namespace {

void check_outputs(const Options& o) {
  const std::pair<const char*, const std::string*> files[] = {{"--json", &o.json_file},
                                                              {"--csv", &o.csv_file},
                                                              {"--table", &o.table_file},
                                                              {"--per-particle", &o.per_particle_file},
                                                              {"--history", &o.history_file}};
  for (const auto& [option, path] : files)
    if (!path->empty()) check_output_path(option, *path);
  if (!o.plot_file.empty()) check_plot_path("--plot", o.plot_file);
}

// SPEC §4: a closed form is trusted only after its audit passes, on this study's physics.
void audit_closed_form(const Case& test_case, const Physics& physics, double t_end) {
  const BaselineAudit audit = audit_case(test_case, physics, t_end);
  if (audit.passed) return;
  char why[256];
  std::snprintf(why, sizeof why,
                "its closed form failed the audit (ODE residual %.2e, CVODE distance %.2e, %d non-finite; "
                "limits 1e-8, 1e-9): refusing it as a reference (see dlpverify audit)",
                audit.residual, audit.cvode_distance, audit.non_finite);
  throw InputError("--case", test_case.name, why);
}

}  // namespace

StudySetup resolve_setup(Options& o, Command command) {
  validate(o, command);
  StudySetup s;
  s.test_case = &find_case(o.case_name);

  const CaseDefaults& defaults = s.test_case->defaults;
  if (!o.t_end) o.t_end = defaults.t_end;
  if (!o.dt) o.dt = defaults.dt;
  if (!o.levels) o.levels = defaults.levels;
  if (!o.reference) o.reference = s.test_case->solution ? "exact" : "cvode";
  s.lattice.shape = o.shape == "sphere" ? Shape::sphere : Shape::shell;
  s.lattice.outer = o.outer;
  if (!o.inner) o.inner = Lattice::default_inner(s.lattice.shape, o.outer);
  s.lattice.inner = *o.inner;
  if (!o.spacing) o.spacing = o.parameters.diameter;
  s.lattice.spacing = *o.spacing;
  s.lattice.z_axis_only = s.test_case->z_axis_only;
  s.launch.expansion_speed = o.expansion_speed;

  s.physics.parameters = o.parameters;
  s.physics.terms = s.test_case->terms;

  s.reference.kind = *o.reference == "exact" ? ReferenceKind::exact : ReferenceKind::cvode;
  if (s.reference.kind == ReferenceKind::exact && !s.test_case->solution)
    throw InputError("--reference", "exact", "case " + s.test_case->name + " has no closed form; use cvode");
  s.reference.rtol = o.reference_rtol;
  s.reference.max_steps = o.max_steps;  // bounds every CVODE solve, the reference's too
  s.reference.openmp_vector = o.vector == "openmp";

  s.plan.t_end = *o.t_end;
  s.plan.coarsest_dt = *o.dt;
  s.plan.ratio = o.ratio;
  s.plan.levels = *o.levels;
  s.plan.variables = measured_variables(s.physics.terms);
  level_steps(s.plan);  // throws when a level's step count is not whole
  if (s.physics.terms.burning) exact::check_before_burn_out(s.physics.parameters, s.plan.t_end);

  check_outputs(o);
  if (s.reference.kind == ReferenceKind::exact) audit_closed_form(*s.test_case, s.physics, s.plan.t_end);
  return s;
}

}  // namespace dlpverify::cli
