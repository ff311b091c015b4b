#include "cli/precision_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>

#include <omp.h>

#include "dlpverify/reference.hpp"
#include "cli/distributed_study.hpp"
#include "cli/setup.hpp"
#include "cli/study_journal.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/work_precision.hpp"
#include "harness/exact_record.hpp"
#include "harness/step_unit.hpp"
#include "cli/problems.hpp"
#include "integrators/registry.hpp"
#include "io/atomic_file.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"
#include "cli/study_inputs.hpp"

namespace dlpverify::cli {

namespace {

// Everything the study needs, resolved and validated before any work or output.
struct ResolvedPrecision {
  StudySetup setup;            // case, cloud, physics, the fixed-step levels, the reference
  std::vector<double> rtols;   // CVODE's sweep
  CvodeSettings cvode;         // rtol, atol and method are set per run
};

ResolvedPrecision resolve(PrecisionOptions& o) {
  // The fixed-step method beside CVODE: CVODE is already swept, by tolerance.
  const IntegratorTraits traits = find_integrator_traits(o.integrator).value_or(IntegratorTraits{});
  if (traits.cvode_settings)
    throw InputError("--integrator", o.integrator,
                     "precision sweeps CVODE itself (adams and bdf); name a fixed-step method: rk2, euler, heun, rk4 "
                     "or arkode-erk:TABLE");
  if (traits.runs_program)
    throw InputError("--integrator", o.integrator,
                     "precision runs built-in methods only (a program of yours reports no step or right-hand-side "
                     "counts); use converge or check");
  if (make_study_integrator(o.integrator, {}, o.problem.case_name)->order() <= 0)  // validates the name too
    throw InputError("--integrator", o.integrator, "is not a fixed-step method");
  validate(o);
  refuse_shared_files(study_inputs(o), named_paths(output_files(o)));
  ResolvedPrecision r;
  r.setup = resolve_setup(o.problem, o.levels, o.reference, o.solver, output_files(o), state_copies(true, false, false));

  r.rtols = tolerance_sweep(o.rtol_max, o.rtol_min, o.per_decade);
  // A CVODE reference at the sweep's own tolerance would measure the tightest runs against
  // themselves (Adams reproduces its own result bit for bit): keep it a decade below at least.
  if (r.setup.reference.kind == ReferenceKind::cvode && o.reference.rtol > r.rtols.back() / 10.0 * (1.0 + 1e-9))
    throw InputError("--reference-rtol", value_text(o.reference.rtol),
                     "must be at most the tightest rtol / 10 = " + value_text(r.rtols.back() / 10.0) +
                         ", or the tightest runs measure the reference against itself");

  r.cvode = cvode_settings(CvodeOptions{}, o.solver);  // rtol, atol and method are set per run
  r.cvode.across_ranks = distribution().ranks() > 1;  // each rank solves its share (docs/mpi.md)
  return r;
}

// CVODE Adams and BDF over the sweep, then the fixed-step method at each level. Every run starts
// from a copy of `initial` with a fresh integrator, so none inherits another's state.
std::vector<PrecisionRun> make_runs(const ResolvedPrecision& r, const std::string& fixed_step, const Problem& problem,
                                    const State& initial) {
  const double t_end = r.setup.plan.t_end;
  const double t0 = problem.initial_time();
  std::vector<PrecisionRun> runs;
  for (const CvodeMethod method : {CvodeMethod::adams, CvodeMethod::bdf}) {
    for (const double rtol : r.rtols) {
      CvodeSettings settings = r.cvode;
      settings.method = method;
      settings.rtol = rtol;
      settings.atol = absolute_tolerances(problem, initial, rtol);
      settings.max_step = t_end;  // no step limit but the duration
      const auto solve = [settings, &problem, &initial, t0, t_end](SolverStatistics& statistics) {
        CvodeIntegrator integrator(settings);
        State state = initial;
        integrator.solve(problem, state, t0, t0 + t_end);
        statistics = integrator.statistics();
        return problem.measured(state, t_end);
      };
      runs.push_back({method == CvodeMethod::adams ? "adams" : "bdf", rtol, std::nullopt, solve});
    }
  }
  for (const long steps : level_steps(r.setup.plan)) {
    const double dt = t_end / static_cast<double>(steps);  // lands on t_end whatever the ratio
    const CvodeSettings& across = r.cvode;  // arkode-erk spans the ranks as CVODE does
    const auto solve = [fixed_step, across, &problem, &initial, t0, t_end, dt, steps](SolverStatistics& statistics) {
      const std::unique_ptr<Integrator> integrator = make_study_integrator(fixed_step, across, problem.name());
      State state = initial;
      integrator->advance(problem, state, t0, dt, steps);
      statistics = integrator->statistics();
      return problem.measured(state, t_end);
    };
    runs.push_back({fixed_step, std::nullopt, dt, solve});
  }
  return runs;
}

}  // namespace

int run_precision_command(PrecisionOptions options, const std::string& command_line) {
  const ResolvedPrecision resolved = resolve(options);
  const StudySetup& r = resolved.setup;
  if (options.threads > 0) omp_set_num_threads(options.threads);

  // Under mpirun each rank solves its own members (docs/mpi.md); `whole` is what the report and
  // the journal describe, and rank 0 alone keeps the journal.
  check_distributable(options.integrator, r.reference);
  const Problem& whole = *r.problem;
  const RankShare share(whole);
  const Problem& problem = share.problem();
  const State initial = problem.initial_state();
  const double t0 = problem.initial_time();

  // The journal (study_journal.hpp): runs finished before are taken, each new one recorded, and
  // SIGINT/SIGTERM stop the sweep after the run under way.
  const std::vector<PrecisionRun> runs = make_runs(resolved, options.integrator, problem, initial);
  const nlohmann::json options_json = to_json(options);
  nlohmann::json identity = study_identity(whole, r.plan, r.reference);
  identity["runs"] = nlohmann::json::array();
  for (const PrecisionRun& run : runs) identity["runs"].push_back(run_label(run.method, run.rtol, run.dt));
  const bool journal_rank = distribution().rank() == 0;
  StudyJournal journal(journal_rank ? options.outputs.json_file : std::string(), journal_rank ? journal_start(options.resume, options.restart) : JournalStart::fresh,
                       "precision", options_json, identity);
  const std::vector<Variable>& variables = r.plan.variables;
  std::unique_ptr<StopOnSignal> rank_signals;
  const Progress<PrecisionRunResult> progress = shared_progress(
      journal.progress<PrecisionRunResult>(
          [&variables](const nlohmann::json& record) { return run_from_record(record, variables); },
          [&variables](const PrecisionRunResult& run) { return run_record(run, variables); }),
      journal.active(), variables, rank_signals);

  Reference reference;
  WorkPrecisionResult result;
  try {
    // Recomputed on every run, a resumed one too: a closed form or CVODE is deterministic.
    reference = compute_reference(problem, r.reference, initial, r.plan.t_end, r.plan.variables);
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": reference: " + e.what());
  }
  try {
    result = run_work_precision(runs, problem.measured(reference.state, r.plan.t_end), reference.error_estimate,
                                r.plan.variables, progress);
    if (progress.stop && progress.stop()) throw StudyStopped(static_cast<int>(runs.size()));
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": " + e.what());
  } catch (const StudyStopped& e) {
    // Under mpirun the ranks without the journal end with rank 0's code.
    if (!journal.active()) return kExitStoppedBySignal;
    return journal.stopped(e.levels_done(), static_cast<int>(runs.size()), "runs");
  }
  if (distribution().rank() != 0) return kExitDone;  // rank 0 reports (src/mpi/session.hpp)

  WorkPrecisionDescription description;
  description.case_name = problem.name();
  description.reference = reference.kind;
  description.reference_detail = reference.detail;
  description.reference_statistics = reference.statistics;
  description.particles = whole.members();
  description.t0 = t0;
  description.t_end = r.plan.t_end;
  description.time_unit = step_unit(problem);
  description.options = options_json;
  description.provenance = provenance(command_line);

  const std::string table = format_table(description, result);
  const nlohmann::json json = to_json(description, result);
  // Every output is written and flushed before any replaces its old file (a failure on one leaves
  // them all as they were), and the console table comes after them.
  const OutputOptions& out = options.outputs;
  OutputSet outputs;
  if (wanted(out.plot_file))
    outputs.add(out.plot_file, plot_work_precision({json}, PlotOptions{out.plot_file, out.title, "--plot", false, {}}));
  if (wanted(out.json_file)) outputs.add(out.json_file, json_text(json, 2) + "\n");
  if (wanted(out.csv_file)) outputs.add(out.csv_file, format_csv(description, result));
  if (wanted(out.table_file)) outputs.add(out.table_file, table);
  outputs.commit();
  if (!any_on_standard_output(output_files(options))) std::cout << table << std::flush;
  journal.finish();
  return kExitDone;
}

}  // namespace dlpverify::cli
