#include "case_study/precision.hpp"

#include <memory>

#include <omp.h>

#include "case_study/inputs.hpp"
#include "case_study/setup.hpp"
#include "families/study_integrators.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/level_stop.hpp"
#include "harness/distribution.hpp"
#include "dlpverify/precision_request.hpp"
#include "study/journal.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"

namespace dlpverify::case_study {

using namespace families;

namespace {

// The case, its levels and reference, validated before any work or output.
StudySetup resolve(PrecisionOptions& o) {
  // The fixed-step method beside CVODE: CVODE is already swept, by tolerance.
  const IntegratorTraits traits = find_integrator_traits(o.integrator).value_or(IntegratorTraits{});
  if (traits.cvode_settings) {
    std::string methods;
    for (const std::string& name : runge_kutta_names()) methods += name + ", ";
    methods.resize(methods.size() - 2);
    throw InputError("--integrator", o.integrator,
                     "precision sweeps CVODE itself (adams and bdf); name a fixed-step method: " + methods +
                         " or arkode-erk:TABLE");
  }
  if (traits.runs_program)
    throw InputError("--integrator", o.integrator,
                     "precision runs built-in methods only (a program of yours reports no step or right-hand-side "
                     "counts); use converge or check");
  if (make_study_integrator(o.integrator, {}, o.problem.case_name)->order() <= 0)  // validates the name too
    throw InputError("--integrator", o.integrator, "is not a fixed-step method");
  validate(o);
  refuse_shared_files(study_inputs(o), named_paths(output_files(o), true));
  return resolve_setup(o.problem, o.levels, o.reference, o.solver, output_files(o), state_copies(true, false, false));
}

// CVODE Adams and BDF over the sweep (atol = rtol × each field's scale), then the fixed-step method
// at the levels.
PrecisionRequest precision_request(const PrecisionOptions& o, const StudySetup& setup, const std::string& command_line) {
  PrecisionRequest request;
  request.problem = setup.problem.get();
  request.rtols = tolerance_sweep(o.rtol_max, o.rtol_min, o.per_decade);
  CvodeSettings cvode = cvode_settings(CvodeOptions{}, o.solver);  // rtol, atol and method are set per run
  cvode.across_ranks = distribution().ranks() > 1;  // each rank solves its share; arkode-erk too (docs/mpi.md)
  const IntegratorCatalog::Found swept = *study_catalog().find("cvode");
  for (const CvodeMethod method : {CvodeMethod::adams, CvodeMethod::bdf}) {
    CvodeSettings settings = cvode;
    settings.method = method;
    request.adaptive.push_back({method == CvodeMethod::adams ? "adams" : "bdf",
                                swept.entry->at_tolerance(swept.argument, IntegratorContext{settings, {}, std::nullopt}),
                                swept.entry->info.traits.reach});
  }
  request.fixed_step = o.integrator;
  request.fixed_step_reach = integrator_traits(o.integrator).reach;
  request.make_fixed_step = [name = o.integrator, cvode, case_name = o.problem.case_name](const Problem&) {
    return make_study_integrator(name, cvode, case_name);
  };
  request.plan = setup.plan;
  request.reference = setup.reference;
  request.options = to_json(o);
  request.provenance = provenance(command_line);
  return request;
}

}  // namespace

CaseOutcome run_precision(PrecisionOptions& options, const std::string& command_line) {
  const StudySetup setup = resolve(options);
  check_journal_place(options.outputs.json_file, journal_terms());
  const PrecisionRequest request = precision_request(options, setup, command_line);
  if (options.threads > 0) omp_set_num_threads(options.threads);

  // The journal (study/journal.hpp): runs finished before are taken, each new one recorded, and
  // SIGINT/SIGTERM stop the sweep after the run under way. Under mpirun rank 0 alone keeps it and
  // shares its runs.
  nlohmann::json identity = study_identity(*setup.problem, setup.plan, setup.reference);
  identity["runs"] = run_labels(request);
  const std::size_t runs = identity["runs"].size();
  StudyJournal journal(options.outputs.json_file, journal_start(options.resume, options.restart), "precision",
                       request.options, identity, journal_terms());
  const Progress<PrecisionRunResult> progress = journal.runs(setup.plan.variables);

  PrecisionOutcome outcome;
  try {
    outcome = dlpverify::run(request, progress);
  } catch (const StudyStopped& e) {
    // Under mpirun the ranks without the journal end with rank 0's code.
    return {journal.stopped(e.levels_done(), static_cast<int>(runs), "runs"), ""};
  } catch (const LevelAbandoned&) {
    return {journal.stopped(journal.kept(), static_cast<int>(runs), "runs"), ""};
  }
  if (!outcome.reported) return {};  // the command's outcome is rank 0's (src/mpi/session.hpp)

  // Every output is written and flushed before any replaces its old file (a failure on one leaves
  // them all as they were), and the console table comes after them.
  const OutputOptions& out = options.outputs;
  OutputSet outputs;
  if (wanted(out.plot_file))
    outputs.add(out.plot_file, plot_work_precision({outcome.report}, PlotOptions{out.plot_file, out.title, "--plot", false, {}}));
  if (wanted(out.json_file)) outputs.add(out.json_file, json_text(outcome.report, 2) + "\n");
  if (wanted(out.csv_file)) outputs.add(out.csv_file, format_csv(outcome.description, outcome.result));
  if (wanted(out.table_file)) outputs.add(out.table_file, outcome.table);
  outputs.commit();
  journal.finish();
  return {kExitDone, any_on_standard_output(output_files(options)) ? "" : outcome.table};
}

}  // namespace dlpverify::case_study
