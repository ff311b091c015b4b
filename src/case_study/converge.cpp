#include "case_study/converge.hpp"

#include <chrono>
#include <filesystem>
#include <optional>

#include <omp.h>

#include "case_study/ci_report.hpp"
#include "case_study/html_report.hpp"
#include "case_study/inputs.hpp"
#include "case_study/outputs.hpp"
#include "case_study/setup.hpp"
#include "case_study/summary.hpp"
#include "case_study/tolerance.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/history.hpp"
#include "dlpverify/level_stop.hpp"
#include "dlpverify/member_coordinate.hpp"
#include "dlpverify/recorded_study.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study_request.hpp"
#include "families/study_integrators.hpp"
#include "harness/distribution.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/junit_xml.hpp"
#include "io/provenance.hpp"
#include "study/journal.hpp"

namespace dlpverify::case_study {

using families::integrator_traits;
using families::make_study_integrator;

namespace {

using OutputFiles = std::vector<std::pair<std::string, std::string>>;

// What decides the levels besides the options (study/journal.hpp).
nlohmann::json identity(const StudySetup& r, const Integrator& integrator) {
  nlohmann::json identity = study_identity(*r.problem, r.plan, r.reference);
  identity.update({{"integrator", integrator.name()}, {"integrator_order", integrator.order()}});
  return identity;
}

// The request of converge, and of check when `check` is given (docs/architecture.md, "The study").
StudyRequest study_request(const ConvergeOptions& options, const CheckOptions* check, const StudySetup& setup,
                           const CvodeSettings& cvode, const exchange::ExecSettings& exec, IntegratorReach reach,
                           const std::string& command_line) {
  StudyRequest request;
  request.problem = setup.problem.get();
  request.make_integrator = [&options, cvode, exec](const Problem& share) {
    CvodeSettings settings = cvode;
    if (options.cvode.atol) settings.atol = absolute_tolerances(share, share.initial_state(), *options.cvode.atol);
    return make_study_integrator(options.integrator, settings, options.problem.case_name, exec);
  };
  request.reach = reach;
  request.plan = setup.plan;
  request.reference = setup.reference;
  if (options.levels.auto_levels) {
    request.search.emplace();
    request.search->order_half_width = options.search.order_ci;
    request.search->budget_seconds = options.search.budget;
  }
  if (check) {
    StudyExpectation& expect = request.check.emplace();
    expect.order = *check->expect_order;
    expect.order_tolerance = check->order_tolerance;
    expect.constant_tolerance = check->constant_tolerance;
    request.escalate = !check->no_escalate;
    // Read before any work or journal: a file that is not a study result is refused at once.
    if (!check->baseline.empty()) expect.baseline = read_recorded_study_file(check->baseline, "baseline");
  }
  request.history_outputs = wanted(options.history_file) ? options.history_outputs : 0;
  request.keep_member_states = wanted(options.per_particle_file);
  request.options = check ? to_json(*check) : to_json(options);
  request.provenance = provenance(command_line);
  return request;
}

// The case set up for the integrator under test, and the request of its study, all checked before
// any work or file.
struct PreparedStudy {
  StudySetup setup;
  StudyRequest request;  // points into setup
  nlohmann::json identity;
  std::string name;  // in a suite's summary and the CI reports (case_study/ci_report.hpp)
  const MemberCoordinate* coordinate = nullptr;  // the per-particle output's, when the problem has one
};

PreparedStudy prepare(ConvergeOptions& options, const CheckOptions* check, const OutputFiles& files,
                      const std::string& command_line) {
  CvodeSettings cvode = cvode_settings(options.cvode, options.solver);
  cvode.across_ranks = distribution().ranks() > 1;  // each rank steps its share (docs/mpi.md)
  const exchange::ExecSettings exec = exec_settings(options);
  const auto integrator = make_study_integrator(options.integrator, cvode, options.problem.case_name, exec);  // validates the name
  const IntegratorTraits traits = integrator_traits(options.integrator);
  check_manufactured_integrator(options.reference, options.integrator, traits);
  PreparedStudy p;
  p.setup = resolve_setup(options.problem, options.levels, options.reference, options.solver, files,
                          state_copies(traits.state_vectors, wanted(options.history_file), wanted(options.per_particle_file),
                                       traits.stage_vectors),
                          exec);
  p.coordinate = p.setup.problem->capability<MemberCoordinate>();
  if (!options.per_particle_file.empty() && !p.coordinate)
    throw InputError("--per-particle", options.per_particle_file,
                     "writes each particle's similarity coordinate xi; case " + options.problem.case_name + " has none");
  p.setup.plan.expected_order = check ? *check->expect_order : integrator->order();
  if (check) {
    p.setup.plan.expected_order_by_variable = check->expect_order_by_variable;
    check_expected_orders(p.setup.plan);  // each names a measured variable, before any work
  }
  p.request = study_request(options, check, p.setup, cvode, exec, traits.reach, command_line);
  p.identity = identity(p.setup, *integrator);
  p.name = study_name(options.config, p.setup.problem->name(), integrator->name());
  return p;
}

// The case's outcome as the study's outcome gives it: the exit code, the console table, and each
// variable's verdict. The name and where the table goes are the caller's.
CaseOutcome case_outcome(const StudyOutcome& outcome, double seconds) {
  CaseOutcome result(outcome.exit_code(), outcome.table);
  result.table = outcome.table;
  result.report = outcome.report;
  result.seconds = seconds;
  if (outcome.verdict) result.verdicts = variable_verdicts(outcome.result, *outcome.verdict);
  return result;
}

// Every output is written and flushed before any replaces its old file (a failure on one leaves
// them all as they were).
void write_outputs(const ConvergeOptions& options, const CheckOptions* check, const PreparedStudy& p,
                   const StudyOutcome& outcome, const CaseOutcome& result) {
  OutputSet outputs;
  if (check && wanted(check->junit_file)) outputs.add(check->junit_file, junit_xml({junit_suite(result.study, result)}));
  if (check && wanted(check->html_file))
    outputs.add(check->html_file, html_report(result.study, {SuiteStudy{result.study, "", result, kExitDone, "", result.seconds}}));
  if (check && wanted(check->summary_file))
    outputs.add(check->summary_file, check_summary(SuiteStudy{result.study, "", result, kExitDone, "", result.seconds}));
  add_study_outputs(outputs, options.outputs, options.plot_relative, outcome.description, outcome.result,
                    outcome.report, outcome.table);
  if (wanted(options.history_file))
    outputs.add(options.history_file,
                format_history(outcome.history, outcome.result.plan.variables, outcome.description.time_unit));
  if (wanted(options.per_particle_file))
    outputs.add(options.per_particle_file,
                format_per_particle(outcome.result, outcome.reference_state,
                                    p.coordinate->member_coordinate(0, p.setup.problem->members())));
  outputs.commit();
}

}  // namespace

void write_failure_reports(const CheckOptions& check, int code, const std::string& line, double seconds) {
  if (distribution().rank() != 0 || (!wanted(check.junit_file) && !wanted(check.summary_file))) return;
  try {
    validate_outputs(output_files(check), check.config);
    check_outputs({{"--junit", check.junit_file}, {"--summary", check.summary_file}});
  } catch (const InputError&) {
    return;
  }
  const std::string name = study_name(check.config, check.problem.case_name, check.integrator);
  OutputSet outputs;
  if (wanted(check.junit_file)) outputs.add(check.junit_file, junit_xml({junit_error_suite(name, code, line, seconds)}));
  if (wanted(check.summary_file)) outputs.add(check.summary_file, check_summary(SuiteStudy{name, "", std::nullopt, code, line, seconds}));
  outputs.commit();
}

CaseOutcome run_case(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line) {
  if (check)
    validate(*check);
  else
    validate(options);
  const OutputFiles files = check ? output_files(*check) : output_files(options);
  refuse_shared_files(study_inputs(options, check), named_paths(files, true));
  if (options.tolerances.range) return run_tolerance_study(options, check, command_line);
  check_journal_place(options.outputs.json_file, journal_terms());  // before the reference's work
  const PreparedStudy p = prepare(options, check, files, command_line);
  if (options.threads > 0) omp_set_num_threads(options.threads);  // per rank under mpirun

  // The journal (study/journal.hpp): levels finished before are taken, each new one recorded,
  // and SIGINT/SIGTERM stop the study after the level under way. Under mpirun rank 0 alone keeps
  // it and shares its levels.
  StudyJournal journal(options.outputs.json_file, journal_start(options.resume, options.restart),
                       check ? "check" : "converge", p.request.options, p.identity, journal_terms());
  const StudyProgress progress = journal.levels(p.setup.plan.variables);
  StudyOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    outcome = dlpverify::run(p.request, progress);
  } catch (const StudyStopped& e) {
    // Only a journal's signal stops a study; under mpirun the ranks without it end with rank 0's code.
    return {journal.stopped(e.levels_done(), p.setup.plan.levels, "levels"), ""};
  } catch (const LevelAbandoned&) {
    return {journal.stopped(journal.kept(), p.setup.plan.levels, "levels"), ""};
  } catch (const InputError& e) {
    // The levels are sound, the baseline is not this study's: nothing to resume.
    if (e.quantity() == "baseline") journal.finish();
    throw;
  }
  if (!outcome.reported) return {};  // the command's outcome is rank 0's (src/mpi/session.hpp)
  CaseOutcome result =
      case_outcome(outcome, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  result.study = p.name;
  if (any_on_standard_output(files)) result.console.clear();  // the output there takes its place
  write_outputs(options, check, p, outcome, result);
  journal.finish();
  return result;
}

}  // namespace dlpverify::case_study
