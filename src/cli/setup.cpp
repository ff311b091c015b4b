#include "cli/setup.hpp"

#include <algorithm>
#include <cstdio>

#include "cli/options.hpp"
#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/manufactured.hpp"
#include "harness/distribution.hpp"
#include "io/atomic_file.hpp"
#include "io/memory.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

void check_outputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  for (const auto& [option, path] : outputs) {
    if (path.empty()) continue;
    if (option == "--plot")
      check_plot_path(option, path);
    else
      check_output_path(option, path);
  }
}

namespace {

// The study's peak, copies × N × F doubles, against what the machine can still give. Under
// mpirun (docs/mpi.md) each rank checks its own peak: the copies of its share of the members
// (every problem builds a rank's members alone, dlpverify/initial_members.hpp), and on rank 0, when
// the per-particle errors are asked for (`gathered`), the two whole states they need: the finest
// state and the reference it gathers. The case's diagnostics are reduced from each rank's share.
void check_memory(const ProblemOptions& o, int copies, bool gathered) {
  const ProblemSize size = problem_size(o);
  const double state = static_cast<double>(size.members) * size.fields * sizeof(double);
  double needed = copies * state;
  std::string what = std::to_string(copies) + " copies of the " + std::to_string(size.members) + " x " +
                     std::to_string(size.fields) + " state, " + byte_text(state) + " each";
  if (distribution().ranks() > 1) {
    const Eigen::Index share = own_members(size.members).count;
    const int whole = distribution().rank() == 0 && gathered ? 2 : 0;
    needed = copies * static_cast<double>(share) * size.fields * sizeof(double) + whole * state;
    what = "on rank " + std::to_string(distribution().rank()) + ": " + std::to_string(copies) + " copies of its " +
           std::to_string(share) + " members' state";
    if (whole > 0) what += " and " + std::to_string(whole) + " of the whole, " + byte_text(state);
  }
  const AvailableMemory available = available_memory();
  if (needed <= static_cast<double>(available.bytes)) return;
  throw InputError(size.option, size.value,
                   "the study needs about " + byte_text(needed) + " of memory (" + what + ") but " +
                       byte_text(static_cast<double>(available.bytes)) + " is available (" + available.source + ")");
}

// docs/model.md §4: a closed form is trusted only after its audit passes, on this study's physics.
void audit_closed_form(const ProblemOptions& o, double t_end) {
  const BaselineAudit audit = audit_case(o, o.case_name, t_end);
  if (audit.passed) return;
  char why[256];
  std::snprintf(why, sizeof why,
                "its closed form failed the audit (ODE residual %.2e, CVODE distance %.2e, %d non-finite; "
                "limits 1e-8, 1e-9): refusing it as a reference (see dlpverify audit)",
                audit.residual, audit.cvode_distance, audit.non_finite);
  throw InputError("--case", o.case_name, why);
}

// The kind --reference names (already validated by validate(options)).
ReferenceKind reference_kind(const std::string& kind) {
  if (kind == "exact") return ReferenceKind::exact;
  if (kind == "cvode") return ReferenceKind::cvode;
  if (kind == "manufactured") return ReferenceKind::manufactured;
  if (integrator_reference_option(kind)) return ReferenceKind::integrator;
  throw InputError("--reference", kind, "must be exact, cvode, manufactured or integrator:SPEC@DT");
}

// --reference integrator:SPEC@DT: the integrator as a study would make it, and DT dividing t_end
// into whole steps by the rule of the levels (level_steps), else InputError naming --reference.
void set_integrator_reference(const std::string& kind, const ProblemOptions& problem,
                              const exchange::ExecSettings& exec, StudySetup& s) {
  const IntegratorReferenceOption option = *integrator_reference_option(kind);
  try {
    s.reference.integrator = make_study_integrator(option.integrator, CvodeSettings{}, problem.case_name, exec);
    s.reference.integrator_reach = integrator_traits(option.integrator).reach;
  } catch (const InputError& e) {
    // The program's own settings (--exec-order, --exec-timeout) keep their names.
    if (e.quantity() == "declared order" || e.quantity() == "program timeout") throw;
    throw InputError("--reference", kind, "SPEC: " + e.reason());
  }
  StudyPlan one_level = s.plan;
  one_level.coarsest_dt = option.dt;
  one_level.levels = 1;
  try {
    level_steps(one_level);
  } catch (const InputError& e) {
    throw InputError("--reference", kind, e.reason());
  }
  s.reference.dt = option.dt;
}


}  // namespace

void check_manufactured_integrator(const ReferenceOptions& reference, const std::string& integrator) {
  if (reference.kind != "manufactured" || integrator_traits(integrator).calls_problem_rhs) return;
  throw InputError("--reference", "manufactured",
                   "--integrator " + integrator + " evaluates its own right-hand side, so it cannot take the manufactured "
                   "source term; use --reference cvode or integrator:SPEC@DT");
}

int state_copies(bool sundials_whole_cloud, bool history, bool per_particle) {
  return (sundials_whole_cloud ? 26 : 4) + (history ? 2 : 0) + (per_particle ? 1 : 0);
}

StudySetup resolve_setup(ProblemOptions& problem, LevelOptions& levels, ReferenceOptions& reference,
                         const SolverOptions& solver, const std::vector<std::pair<std::string, std::string>>& outputs,
                         int state_copies, const exchange::ExecSettings& exec) {
  const CaseEntry& entry = find_case_entry(problem.case_name);
  if (!levels.t_end) levels.t_end = entry.defaults.t_end;
  if (!levels.dt) levels.dt = entry.defaults.dt;
  if (!levels.levels && !levels.auto_levels) levels.levels = entry.defaults.levels;
  fill_case_defaults(problem);
  const bool closed_form = case_has_closed_form(problem);
  if (!reference.kind) reference.kind = closed_form ? "exact" : "cvode";

  StudySetup s;
  s.reference.kind = reference_kind(*reference.kind);
  if (s.reference.kind == ReferenceKind::exact && !closed_form)
    throw InputError("--reference", "exact",
                     "case " + entry.name + " has no closed form with these options; use cvode or integrator:SPEC@DT");
  s.reference.rtol = reference.rtol;
  s.reference.max_steps = solver.max_steps;  // bounds every CVODE solve, the reference's too
  check_reference_settings(s.reference);

  s.plan.t_end = *levels.t_end;
  s.plan.coarsest_dt = *levels.dt;
  s.plan.ratio = levels.ratio;
  s.plan.levels = levels.auto_levels ? 1 : *levels.levels;  // a search starts with one level
  check_plan(s.plan, levels.auto_levels ? 1 : 2);  // its values, and whole step counts
  if (s.reference.kind == ReferenceKind::integrator) set_integrator_reference(*reference.kind, problem, exec, s);
  check_outputs(outputs);
  const bool per_particle = std::any_of(outputs.begin(), outputs.end(), [](const auto& output) {
    return output.first == "--per-particle" && wanted(output.second);
  });
  check_memory(problem, state_copies, per_particle);  // before anything builds the problem (check_duration does for gas)
  check_duration(problem, s.plan.t_end);
  if (s.reference.kind == ReferenceKind::exact) audit_closed_form(problem, s.plan.t_end);

  s.problem = make_problem(problem);
  // y′ = f(t, y) + ŷ′(t) − f(t, ŷ(t)), whose closed form ŷ is the reference (dlpverify/manufactured.hpp).
  if (s.reference.kind == ReferenceKind::manufactured) s.problem = make_manufactured(std::move(s.problem), s.plan.t_end);
  s.plan.variables = s.problem->variables();
  return s;
}

}  // namespace dlpverify::cli
