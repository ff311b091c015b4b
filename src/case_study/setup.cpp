#include "case_study/setup.hpp"

#include <algorithm>
#include <cstdio>

#include "case_study/options.hpp"
#include "families/families.hpp"
#include "families/study_integrators.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/manufactured.hpp"
#include "io/atomic_file.hpp"
#include "plot/plot.hpp"

namespace dlpverify::case_study {

using namespace families;

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

// The kind --reference names (already validated by validate(options)).
ReferenceKind reference_kind(const std::string& kind) {
  if (kind == "exact") return ReferenceKind::exact;
  if (kind == "cvode") return ReferenceKind::cvode;
  if (kind == "manufactured") return ReferenceKind::manufactured;
  if (kind == "extended") return ReferenceKind::extended;
  if (integrator_reference_option(kind)) return ReferenceKind::integrator;
  throw InputError("--reference", kind, "must be exact, cvode, manufactured, extended or integrator:SPEC@DT");
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

void check_manufactured_integrator(const ReferenceOptions& reference, const std::string& integrator,
                                   const IntegratorTraits& traits) {
  if (reference.kind != "manufactured" || traits.calls_problem_rhs) return;
  throw InputError("--reference", "manufactured",
                   "--integrator " + integrator + " evaluates its own right-hand side, so it cannot take the manufactured "
                   "source term; use --reference cvode or integrator:SPEC@DT");
}

int state_copies(bool sundials_whole_cloud, bool history, bool per_particle, int stage_vectors) {
  return (sundials_whole_cloud ? 26 : 4) + stage_vectors + (history ? 2 : 0) + (per_particle ? 1 : 0);
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
  const bool extended = reference.precision == "extended";
  if (!reference.kind) reference.kind = extended ? "extended" : closed_form ? "exact" : "cvode";

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
  s.plan.precision = extended ? Precision::extended : Precision::double_precision;
  s.plan.levels = levels.auto_levels ? 1 : *levels.levels;  // a search starts with one level
  check_plan(s.plan, levels.auto_levels ? 1 : 2);  // its values, and whole step counts
  if (s.reference.kind == ReferenceKind::integrator) set_integrator_reference(*reference.kind, problem, exec, s);
  check_outputs(outputs);
  const bool per_particle = std::any_of(outputs.begin(), outputs.end(), [](const auto& output) {
    return output.first == "--per-particle" && wanted(output.second);
  });
  families::check_memory(problem, state_copies, per_particle);  // before anything builds the problem (check_duration does for gas)
  check_duration(problem, s.plan.t_end);
  if (s.reference.kind == ReferenceKind::exact) families::require_audited_closed_form(problem, s.plan.t_end);

  s.problem = make_problem(problem);
  // y′ = f(t, y) + ŷ′(t) − f(t, ŷ(t)), whose closed form ŷ is the reference (dlpverify/manufactured.hpp).
  if (s.reference.kind == ReferenceKind::manufactured) s.problem = make_manufactured(std::move(s.problem), s.plan.t_end);
  s.plan.variables = s.problem->variables();
  return s;
}

}  // namespace dlpverify::case_study
