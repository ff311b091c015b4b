#include "cli/tolerance_command.hpp"

#include <iostream>
#include <memory>

#include <omp.h>

#include "cli/distributed_study.hpp"
#include "cli/problems.hpp"
#include "cli/setup.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/tolerance_study.hpp"
#include "dlpverify/work_precision.hpp"
#include "exchange/command_template.hpp"
#include "integrators/exec/exec_integrator.hpp"
#include "integrators/sundials/arkode_adaptive.hpp"
#include "integrators/sundials/cvode_integrator.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

namespace {

// The kinds a sweep runs, by their traits: a program of the user's, CVODE (its settings), or an
// ARKODE table with an embedding (the rest of the tolerance-driven entries).
enum class SweptKind { program, cvode, arkode_table };

struct Swept {
  SweptKind kind;
  std::string argument;  // the command, or the table
};

// Only an integrator that takes a tolerance can be swept by one; the outputs of levels have none.
Swept check_tolerance_options(const ConvergeOptions& o) {
  const std::optional<IntegratorCatalog::Found> found = study_catalog().find(o.integrator);
  if (!found || !found->entry->info.traits.tolerance_driven)
    throw InputError("--integrator", o.integrator,
                     "--tolerances sweeps cvode, arkode-adaptive:TABLE or exec:COMMAND with {rtol}");
  const IntegratorTraits& traits = found->entry->info.traits;
  const Swept swept{traits.runs_program ? SweptKind::program
                    : traits.cvode_settings ? SweptKind::cvode
                                            : SweptKind::arkode_table,
                    found->argument};
  if (swept.kind == SweptKind::arkode_table) check_arkode_adaptive_table(swept.argument);
  if (swept.kind == SweptKind::program && swept.argument.find("{rtol}") == std::string::npos)
    throw InputError("--integrator", o.integrator, "has no {rtol} placeholder: it cannot be given a tolerance");
  for (const auto& [option, path] : std::vector<std::pair<std::string, std::string>>{
           {"--csv", o.outputs.csv_file}, {"--history", o.history_file},
           {"--per-particle", o.per_particle_file}})
    if (!path.empty()) throw InputError(option, path, "is an output of levels; --tolerances writes --json, --table and --plot");
  return swept;
}

// One run per rtol from a fresh integrator and the initial state, over the whole duration.
std::vector<ToleranceRun> make_runs(const ConvergeOptions& o, const Swept& swept, const std::vector<double>& rtols,
                                    const Problem& problem, const State& initial, double t_end) {
  const double t0 = problem.initial_time();
  std::vector<ToleranceRun> runs;
  for (const double rtol : rtols) {
    if (swept.kind == SweptKind::program) {
      // {atol} is --atol when given, else rtol: a number, the program scales it as it sees fit.
      exchange::ExecSettings settings = exec_settings(o);
      settings.command = exchange::fill_placeholders(
          swept.argument,
          {{"rtol", exchange::exact_text(rtol)}, {"atol", exchange::exact_text(o.cvode.atol.value_or(rtol))}});
      runs.push_back({rtol, [settings, &problem, &initial, t0, t_end](SolverStatistics& statistics) {
                        exchange::ExecIntegrator integrator(settings);
                        State state = initial;
                        integrator.advance(problem, state, t0, t_end, 1);  // the program chooses its steps
                        statistics = integrator.statistics();
                        return problem.measured(std::move(state), t_end);
                      }});
      continue;
    }
    if (swept.kind == SweptKind::arkode_table) {
      ArkodeAdaptiveSettings settings{swept.argument, rtol,
                                      absolute_tolerances(problem, initial, o.cvode.atol ? *o.cvode.atol / o.cvode.rtol * rtol : rtol),
                                      o.solver.max_steps, distribution().ranks() > 1};
      runs.push_back({rtol, [settings, &problem, &initial, t0, t_end](SolverStatistics& statistics) {
                        State state = initial;
                        solve_arkode_adaptive(problem, state, t0, t0 + t_end, settings, statistics);
                        return problem.measured(std::move(state), t_end);
                      }});
      continue;
    }
    CvodeSettings settings = cvode_settings(o.cvode, o.solver);
    settings.rtol = rtol;
    settings.atol = absolute_tolerances(problem, initial, o.cvode.atol ? *o.cvode.atol / o.cvode.rtol * rtol : rtol);
    settings.max_step = t_end;
    settings.across_ranks = distribution().ranks() > 1;  // each rank solves its share (docs/mpi.md)
    runs.push_back({rtol, [settings, &problem, &initial, t0, t_end](SolverStatistics& statistics) {
                      CvodeIntegrator integrator(settings);
                      State state = initial;
                      integrator.solve(problem, state, t0, t0 + t_end);
                      statistics = integrator.statistics();
                      return problem.measured(std::move(state), t_end);
                    }});
  }
  return runs;
}

}  // namespace

int run_tolerance_study(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line) {
  const Swept swept = check_tolerance_options(options);
  parse_tolerance_range(options.tolerances);
  const std::vector<double> rtols =
      tolerance_sweep(options.tolerances.rtol_max, options.tolerances.rtol_min, options.tolerances.per_decade);
  StudySetup r = resolve_setup(options.problem, options.levels, options.reference, options.solver, output_files(options),
                               state_copies(true, false, false), exec_settings(options));
  // A CVODE reference at the sweep's own tolerance would measure the tightest runs against themselves.
  if (r.reference.kind == ReferenceKind::cvode && options.reference.rtol > rtols.back() / 10.0 * (1.0 + 1e-9))
    throw InputError("--reference-rtol", value_text(options.reference.rtol),
                     "must be at most the tightest rtol / 10 = " + value_text(rtols.back() / 10.0));
  if (options.threads > 0) omp_set_num_threads(options.threads);
  // Under mpirun each rank solves its own members, the solvers' sums spanning every rank
  // (docs/mpi.md); `whole` is what the report describes.
  check_distributable(options.integrator, r.reference);
  const Problem& whole = *r.problem;
  const RankShare share(whole);
  const Problem& problem = share.problem();
  const State initial = problem.initial_state();
  const double t_end = r.plan.t_end;

  Reference reference;
  ToleranceStudy study;
  try {
    reference = compute_reference(problem, r.reference, initial, t_end, r.plan.variables);
    study = run_tolerance_study(make_runs(options, swept, rtols, problem, initial, t_end),
                                problem.measured(reference.state, t_end), reference.error_estimate, r.plan.variables);
  } catch (const SolverError& e) {
    throw SolverError("case " + problem.name() + ": " + e.what());
  }
  if (distribution().rank() != 0) return kExitDone;  // rank 0 reports (src/mpi/session.hpp)
  std::optional<CheckVerdict> verdict;
  if (check) verdict = check_proportionality(study, check->expect_proportionality, check->proportionality_tolerance);

  const nlohmann::json options_json = check ? to_json(*check) : to_json(options);
  const std::string header = "case " + problem.name() + " · integrator " + options.integrator + " by tolerance · reference " +
                             reference.kind + " (" + reference.detail + ")\n" + std::to_string(whole.members()) +
                             " particles · t_end = " + printf_string("%.6g", t_end) + " after t0";
  const std::string table = format_tolerance_table(header, study, verdict);
  nlohmann::json json = to_json(study, verdict);
  json["variables"] = nlohmann::json::array();
  for (const Variable& v : r.plan.variables) json["variables"].push_back(v.name);
  json.update({{"case", problem.name()}, {"integrator", options.integrator}, {"reference", reference.kind},
               {"reference_detail", reference.detail}, {"particles", whole.members()}, {"t_end", t_end},
               {"options", options_json}, {"provenance", provenance(command_line)}});
  OutputSet outputs;
  if (wanted(options.outputs.plot_file))
    outputs.add(options.outputs.plot_file,
                plot_tolerance(json, PlotOptions{options.outputs.plot_file, options.outputs.title, "--plot", false, {}}));
  if (wanted(options.outputs.json_file)) outputs.add(options.outputs.json_file, json_text(json, 2) + "\n");
  if (wanted(options.outputs.table_file)) outputs.add(options.outputs.table_file, table);
  outputs.commit();
  if (!any_on_standard_output(output_files(options))) std::cout << table << std::flush;
  return verdict && !verdict->passed ? kExitCheckFailed : kExitDone;
}

}  // namespace dlpverify::cli
