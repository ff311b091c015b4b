#include "case_study/tolerance.hpp"

#include <chrono>

#include <omp.h>

#include "families/families.hpp"
#include "families/study_integrators.hpp"
#include "case_study/ci_report.hpp"
#include "case_study/setup.hpp"
#include "case_study/summary.hpp"
#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"
#include "dlpverify/tolerance_request.hpp"
#include "dlpverify/work_precision.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/junit_xml.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"

namespace dlpverify::case_study {

using namespace families;

namespace {

// The integrator at any rtol: only one that takes a tolerance can be swept by one, and the outputs
// of levels have none.
SolveAtTolerance swept_integrator(const ConvergeOptions& o) {
  const std::optional<IntegratorCatalog::Found> found = study_catalog().find(o.integrator);
  if (!found || !found->entry->at_tolerance)
    throw InputError("--integrator", o.integrator,
                     "--tolerances sweeps cvode, arkode-adaptive:TABLE or exec:COMMAND with {rtol}");
  CvodeSettings cvode = cvode_settings(o.cvode, o.solver);
  cvode.across_ranks = distribution().ranks() > 1;  // each rank solves its share (docs/mpi.md)
  SolveAtTolerance solve = found->entry->at_tolerance(found->argument, IntegratorContext{cvode, exec_settings(o), o.cvode.atol});
  for (const auto& [option, path] : std::vector<std::pair<std::string, std::string>>{
           {"--csv", o.outputs.csv_file}, {"--history", o.history_file},
           {"--per-particle", o.per_particle_file}})
    if (!path.empty()) throw InputError(option, path, "is an output of levels; --tolerances writes --json, --table and --plot");
  return solve;
}

ToleranceRequest tolerance_request(const ConvergeOptions& options, const CheckOptions* check, const StudySetup& setup,
                                   SolveAtTolerance solve, const std::string& command_line) {
  ToleranceRequest request;
  request.problem = setup.problem.get();
  request.integrator = options.integrator;
  request.reach = integrator_traits(options.integrator).reach;
  request.solve = std::move(solve);
  request.rtols = tolerance_sweep(options.tolerances.rtol_max, options.tolerances.rtol_min, options.tolerances.per_decade);
  request.t_end = setup.plan.t_end;
  request.variables = setup.plan.variables;
  request.reference = setup.reference;
  if (check) request.check = ProportionalityExpectation{check->expect_proportionality, check->proportionality_tolerance};
  request.options = check ? to_json(*check) : to_json(options);
  request.provenance = provenance(command_line);
  return request;
}

}  // namespace

CaseOutcome run_tolerance_study(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line) {
  SolveAtTolerance solve = swept_integrator(options);
  parse_tolerance_range(options.tolerances);
  const StudySetup setup = resolve_setup(options.problem, options.levels, options.reference, options.solver,
                                         check ? output_files(*check) : output_files(options), state_copies(true, false, false),
                                         exec_settings(options));
  const ToleranceRequest request = tolerance_request(options, check, setup, std::move(solve), command_line);
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const auto start = std::chrono::steady_clock::now();
  const ToleranceOutcome outcome = dlpverify::run(request);
  if (!outcome.reported) return {};  // the command's outcome is rank 0's (src/mpi/session.hpp)

  const auto files = check ? output_files(*check) : output_files(options);
  CaseOutcome result(outcome.exit_code(), any_on_standard_output(files) ? "" : outcome.table);
  if (outcome.verdict) result.verdicts = variable_verdicts(outcome.study.variables, *outcome.verdict);
  for (VariableVerdict& v : result.verdicts) {  // judged by the exponent E of e ≈ C rtol^E
    v.quantity = "exponent";
    for (std::size_t i = 0; i < outcome.study.variables.size(); ++i)
      if (outcome.study.variables[i].name == v.variable && i < outcome.study.proportionality.size())
        v.fit = outcome.study.proportionality[i].exponent;
  }
  result.table = outcome.table;
  result.report = outcome.report;
  result.study = study_name(options.config, options.problem.case_name, options.integrator);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  OutputSet outputs;
  const OutputOptions& out = options.outputs;
  if (check && wanted(check->junit_file)) outputs.add(check->junit_file, junit_xml({junit_suite(result.study, result)}));
  if (check && wanted(check->summary_file))
    outputs.add(check->summary_file, check_summary(SuiteStudy{result.study, "", result, kExitDone, "", result.seconds}));
  if (wanted(out.plot_file))
    outputs.add(out.plot_file, plot_tolerance(outcome.report, PlotOptions{out.plot_file, out.title, "--plot", false, {}}));
  if (wanted(out.json_file)) outputs.add(out.json_file, json_text(outcome.report, 2) + "\n");
  if (wanted(out.table_file)) outputs.add(out.table_file, outcome.table);
  outputs.commit();
  return result;
}

}  // namespace dlpverify::case_study
