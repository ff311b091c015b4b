#include "case_study/sharpness.hpp"

#include <omp.h>

#include "case_study/inputs.hpp"
#include "case_study/setup.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/reference_study.hpp"
#include "integrators/tableau/sharpness.hpp"
#include "integrators/tableau/sharpness_report.hpp"
#include "integrators/tableau/tableau_integrator.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/output_path.hpp"
#include "io/provenance.hpp"

namespace dlpverify::case_study {

namespace {

// The study of an integrator on a case set up by resolve_setup.
IntegratorStudy study_on(const StudySetup& setup) {
  return [&setup](Integrator& integrator) { return dlpverify::run_study(*setup.problem, integrator, setup.plan, setup.reference); };
}

}  // namespace

CaseOutcome run_sharpness(SharpnessOptions& options, const std::string& command_line) {
  validate(options);
  const std::optional<std::string> file = tableau_file_of(options.integrator);
  if (!file) throw InputError("--integrator", options.integrator, "sharpness perturbs a Butcher tableau: give tableau:FILE");
  const RuntimeTableau tableau = read_tableau_file(*file);
  const std::vector<std::pair<std::string, std::string>> outputs{{"--json", options.json_file}};
  refuse_shared_files(integrator_inputs("--integrator", options.integrator), named_paths(outputs));
  ProblemOptions alternative_problem = options.problem;
  LevelOptions alternative_levels = options.levels;
  const StudySetup setup = resolve_setup(options.problem, options.levels, options.reference, options.solver, outputs,
                                         state_copies(false, false, false));
  std::optional<StudySetup> alternative;
  if (options.alternative != "none" && options.alternative != *options.reference.kind) {
    ReferenceOptions reference{options.alternative, options.reference.rtol};
    alternative = resolve_setup(alternative_problem, alternative_levels, reference, options.solver, outputs,
                                state_copies(false, false, false));
  }
  const std::string alternative_name = alternative ? options.alternative : "none";
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const SharpnessSettings settings{options.delta, options.order_tolerance, options.constant_tolerance};
  SharpnessReport report;
  try {
    report = measure_sharpness(tableau, settings, study_on(setup), alternative ? study_on(*alternative) : IntegratorStudy());
  } catch (const SolverError& e) {
    throw SolverError("case " + setup.problem->name() + ": " + e.what());
  }
  const SharpnessOutcome outcome =
      judge_sharpness(tableau, report, setup.problem->name(), *options.reference.kind, alternative_name);
  if (!options.json_file.empty()) {
    nlohmann::json j = outcome.report;
    j["options"] = to_json(options);
    j["provenance"] = provenance(command_line);
    OutputSet set;
    set.add(options.json_file, json_text(j, 2) + "\n");
    set.commit();
  }
  const bool on_standard_output = !options.json_file.empty() && output_target(options.json_file) == OutputTarget::standard_output;
  return {outcome.passed ? kExitDone : kExitCheckFailed, on_standard_output ? "" : outcome.table};
}

}  // namespace dlpverify::case_study
