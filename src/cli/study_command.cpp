#include "cli/study_command.hpp"

#include <iostream>
#include <optional>

#include <omp.h>

#include "cli/distributed_study.hpp"
#include "cli/problems.hpp"
#include "cli/setup.hpp"
#include "cli/study_journal.hpp"
#include "cli/study_outputs.hpp"
#include "cli/tolerance_command.hpp"
#include "dlpverify/case_report.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/history.hpp"
#include "dlpverify/level_search.hpp"
#include "dlpverify/missed_order.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study.hpp"
#include "harness/constant_gate.hpp"
#include "harness/exact_record.hpp"
#include "harness/recorded_study.hpp"
#include "harness/step_unit.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"
#include "integrators/registry.hpp"
#include "cli/study_inputs.hpp"

namespace dlpverify::cli {

namespace {

// What decides the levels besides the options (study_journal.hpp).
nlohmann::json identity(const StudySetup& r, const Integrator& integrator) {
  nlohmann::json identity = study_identity(*r.problem, r.plan, r.reference);
  identity.update({{"integrator", integrator.name()}, {"integrator_order", integrator.order()}});
  return identity;
}

StudyProgress level_progress(StudyJournal& journal, const std::vector<Variable>& variables) {
  return journal.progress<LevelResult>(
      [&variables](const nlohmann::json& record) { return level_from_record(record, variables); },
      [&variables](const LevelResult& level) { return level_record(level, variables); });
}

// check --baseline: the baseline must be of this study (else bad input, before any output is
// written), and each variable's error constant must stay in its band (harness/constant_gate.hpp).
void gate_on_baseline(const RecordedStudy& baseline, const StudyDescription& description, const StudyResult& study,
                      const CheckOptions& check, CheckVerdict& verdict) {
  const RecordedStudy now = read_recorded_study(to_json(description, study, std::nullopt), "this study", "--baseline");
  require_baseline_of(now, baseline, *check.expect_order, "--baseline");
  check_constants(now, baseline, check.constant_tolerance, verdict);
}

// --levels auto: the levels found by search_levels under --order-ci and --budget, stopped by a signal.
LevelRunner level_search(const LevelSearchOptions& options, const std::function<bool()>& stop, LevelSearch& search) {
  LevelSearchRules rules;
  rules.order_half_width = options.order_ci;
  rules.budget_seconds = options.budget;
  return [rules, stop, &search](const StudyPlan& plan, const State& reference,
                                const std::vector<double>& reference_error, const Solve& solve,
                                const TightenReference& tighten) {
    return search_levels(plan, reference, reference_error, solve, rules, search, stop, tighten);
  };
}

// converge, and check when `check` is given (the same options, plus the expected order).
int run_study(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line) {
  refuse_shared_files(study_inputs(options, check), named_paths(output_files(options)));
  if (options.tolerances.range) return run_tolerance_study(options, check, command_line);
  CvodeSettings cvode = cvode_settings(options.cvode, options.solver);
  cvode.across_ranks = distribution().ranks() > 1;  // each rank steps its share (docs/mpi.md)
  const exchange::ExecSettings exec = exec_settings(options);
  const int integrator_order = make_study_integrator(options.integrator, cvode, options.problem.case_name, exec)->order();  // validates the name
  const bool sundials = integrator_traits(options.integrator).state_vectors;
  check_manufactured_integrator(options.reference, options.integrator);
  StudySetup r = resolve_setup(options.problem, options.levels, options.reference, options.solver, output_files(options),
                               state_copies(sundials, wanted(options.history_file), wanted(options.per_particle_file)), exec);
  r.plan.expected_order = check ? *check->expect_order : integrator_order;
  if (options.threads > 0) omp_set_num_threads(options.threads);  // per rank under mpirun

  // Under mpirun each rank solves its own members only (docs/mpi.md); `whole` is the problem the
  // reports and the journal describe.
  const Problem& whole = *r.problem;
  const RankShare share(whole);

  // The cloud's state is held by the problem, the measured reference and the two latest levels
  // only: the initial state is asked of the problem where it is needed, and states are moved
  // into measurement (the memory budget of docs/verification.md, "Memory").
  const Problem& problem = share.problem();
  const double t0 = problem.initial_time();
  const Eigen::Index members = whole.members();
  if (options.cvode.atol) cvode.atol = absolute_tolerances(problem, problem.initial_state(), *options.cvode.atol);
  const auto integrator = make_study_integrator(options.integrator, cvode, options.problem.case_name, exec);
  check_distributable(options.integrator, r.reference);

  // The baseline is read before any work or journal: a file that is not a study result is refused
  // at once.
  const std::optional<RecordedStudy> baseline =
      check && !check->baseline.empty() ? std::optional(read_recorded_study_file(check->baseline, "--baseline")) : std::nullopt;

  // The journal (study_journal.hpp): levels finished before are taken, each new one recorded,
  // and SIGINT/SIGTERM stop the study after the level under way.
  const nlohmann::json options_json = check ? to_json(*check) : to_json(options);
  // Under mpirun rank 0 alone keeps the journal and shares its levels (cli/distributed_study.hpp).
  const bool journal_rank = distribution().rank() == 0;
  StudyJournal journal(journal_rank ? options.outputs.json_file : std::string(), journal_rank ? journal_start(options.resume, options.restart) : JournalStart::fresh,
                       check ? "check" : "converge", options_json, identity(r, *integrator));
  std::unique_ptr<StopOnSignal> rank_signals;
  const StudyProgress progress =
      shared_progress(level_progress(journal, r.plan.variables), journal.active(), r.plan.variables, rank_signals);
  const auto stop_requested = [&progress] { return progress.stop && progress.stop(); };

  StudyResult study;
  std::optional<LevelSearch> search;  // --levels auto: what the search ran and why it stopped
  if (options.levels.auto_levels) search.emplace();
  Reference reference;  // its state: the measured columns the levels are compared with
  std::vector<HistoryPoint> history;
  try {
    // The reference is recomputed on every run, a resumed one too: every kind is deterministic.
    if (options.levels.auto_levels)
      study = dlpverify::run_study_with(problem, *integrator, r.plan, r.reference,
                                        level_search(options.search, progress.stop, *search), &reference);
    else
      study = dlpverify::run_study(problem, *integrator, r.plan, r.reference, progress, &reference);
    if (stop_requested()) throw StudyStopped(r.plan.levels);
    if (wanted(options.history_file)) {
      const LevelResult& finest = study.levels.back();
      const AdvanceSteps advance = [&](State& state, double tau_from, double dt, long steps) {
        integrator->advance(problem, state, t0 + tau_from, dt, steps);
      };
      const Measure measure = [&problem](const State& state, double tau) { return problem.measured(state, tau); };
      const State initial = problem.initial_state();
      history = record_history(initial, r.plan.variables, finest.dt, finest.steps, options.history_outputs, advance,
                               reference_trajectory(problem, r.reference, initial), measure);
    }
    if (stop_requested()) throw StudyStopped(r.plan.levels);
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": " + e.what());
  } catch (const StudyStopped& e) {
    // Only a journal's signal stops a study; under mpirun the ranks without it end with rank 0's code.
    if (!journal.active()) return kExitStoppedBySignal;
    return journal.stopped(e.levels_done(), r.plan.levels, "levels");
  }

  // Rank 0 reports for every rank. The diagnostics are reduced from every rank's own members; only
  // the per-particle errors need every member's finest state and reference on rank 0 (docs/mpi.md).
  const nlohmann::json diagnostics = case_diagnostics(problem, problem.initial_state(), study.finest, r.plan.t_end);
  if (wanted(options.per_particle_file)) {
    study.finest = distribution().gathered_on_root(study.finest);
    reference.state = distribution().gathered_on_root(reference.state);
  }
  if (distribution().rank() != 0) return kExitDone;  // the command's outcome is rank 0's (src/mpi/session.hpp)

  StudyDescription description;
  description.case_name = problem.name();
  description.integrator = integrator->name();
  description.integrator_order = integrator->order();
  description.reference = reference.kind;
  description.reference_detail = reference.detail;
  description.reference_statistics = reference.statistics;
  description.particles = members;
  description.t0 = t0;
  description.time_unit = step_unit(problem);
  description.options = options_json;
  description.provenance = provenance(command_line);
  description.parameters = case_parameters(whole);
  description.diagnostics = diagnostics;

  std::optional<CheckVerdict> verdict;
  if (check) verdict = check_orders(study, *check->expect_order, check->order_tolerance);
  if (verdict && search) {
    judge_by_extrapolated_orders(study, search->extrapolations, *verdict);
    judge_search_coverage(study, *search, *verdict);
  }
  if (baseline) {
    try {
      gate_on_baseline(*baseline, description, study, *check, *verdict);
    } catch (const InputError&) {
      journal.finish();  // the levels are sound, the baseline is not this study's: nothing to resume
      throw;
    }
  }

  StudyReport report = study_report(description, study, verdict);
  if (search) {
    report.table = format_level_search(*search, study) + "\n" + report.table;
    report.result["level_search"] = to_json(*search, study);
  }
  if (verdict && !verdict->passed) {
    MissContext context = miss_context(whole, r.plan.t_end);
    if (search)
      for (const std::optional<OrderExtrapolation>& x : search->extrapolations)
        context.extrapolation.push_back(x ? describe(*x) : std::string());
    const auto reasons = explain_missed_orders(study, *verdict, context);
    report.table += format_missed_orders(study, reasons);
    report.result["missed_order"] = to_json(study, context, reasons);
  }
  // Every output is written and flushed before any replaces its old file (a failure on one leaves
  // them all as they were), and the console table comes after them.
  OutputSet outputs;
  add_study_outputs(outputs, options.outputs, options.plot_relative, description, study, report);
  if (wanted(options.history_file)) outputs.add(options.history_file, format_history(history, r.plan.variables, description.time_unit));
  if (wanted(options.per_particle_file))
    outputs.add(options.per_particle_file,
                format_per_particle(study, reference.state, member_coordinate(whole)));
  outputs.commit();
  if (!any_on_standard_output(output_files(options))) std::cout << report.table << std::flush;
  journal.finish();
  return verdict && !verdict->passed ? kExitCheckFailed : kExitDone;
}

}  // namespace

int run_converge_command(ConvergeOptions options, const std::string& command_line) {
  validate(options);
  return run_study(options, nullptr, command_line);
}

int run_check_command(CheckOptions options, const std::string& command_line) {
  validate(options);
  return run_study(options, &options, command_line);
}

}  // namespace dlpverify::cli
