#include "cli/options.hpp"

#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"

namespace dlpverify::cli {

namespace {

// ---- the groups: options, checks, report ------------------------------------------------------

void add_head(CLI::App& app, std::string& config, std::string& integrator, const char* integrators, ProblemOptions& o) {
  app.add_option("--config", config, "Study file (TOML) holding any of these options as key = value");
  app.add_option("--case", o.case_name, "Verification case (listed below)")->capture_default_str();
  app.add_option("--integrator", integrator, integrators)->capture_default_str();
}

// --levels L or (converge, check) --levels auto: a whole number, or the word that asks for a search.
void add_levels_option(CLI::App& app, LevelOptions& o, bool fixed_step_beside_cvode) {
  const auto set = [&o](const std::string& value) {
    o.auto_levels = value == "auto";
    if (o.auto_levels) {
      o.levels.reset();
      return;
    }
    std::size_t used = 0;
    int levels = 0;
    try {
      levels = std::stoi(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (value.empty() || used != value.size()) throw InputError("--levels", value, "must be a whole number or auto");
    o.levels = levels;
  };
  app.add_option_function<std::string>("--levels", set,
                                       fixed_step_beside_cvode
                                           ? "Levels of the fixed-step method [default: the case's]"
                                           : "Number of levels, or auto: found by the study (--budget, --order-ci) "
                                             "[default: the case's]")
      ->group("Study (docs/model.md §6)");
}

void add_levels(CLI::App& app, LevelOptions& o, int& threads, bool fixed_step_beside_cvode) {
  const std::string study = "Study (docs/model.md §6)";
  app.add_option("--t-end", o.t_end, "Duration after t0 [s] [default: the case's]")->group(study);
  app.add_option("--dt", o.dt,
                 fixed_step_beside_cvode ? "Coarsest step of the fixed-step method [s] [default: the case's]"
                                         : "Coarsest time step [s] [default: the case's]")
      ->group(study);
  add_levels_option(app, o, fixed_step_beside_cvode);
  app.add_option("--ratio", o.ratio, "Refinement ratio r: dt_k = dt / r^k")->capture_default_str()->group(study);
  app.add_option("--threads", threads, "OpenMP threads (0: all cores)")->capture_default_str()->group(study);
}
void add_level_search(CLI::App& app, LevelSearchOptions& o) {
  const std::string study = "Study (docs/model.md §6)";
  app.add_option("--budget", o.budget, "With --levels auto: wall time the levels may take [s]")
      ->capture_default_str()->group(study);
  app.add_option("--order-ci", o.order_ci,
                 "With --levels auto: refine until the fitted order's 95% interval is within ± this")
      ->capture_default_str()->group(study);
}

void add_tolerances(CLI::App& app, ToleranceOptions& o) {
  const std::string group = "Adaptive integrators by tolerance (cvode, arkode-adaptive:TABLE, exec: with {rtol})";
  app.add_option("--tolerances", o.range,
                 "MAX:MIN: run once per rtol from MAX down to MIN instead of at levels (cvode, arkode-adaptive:TABLE, "
                 "exec:COMMAND with {rtol})")
      ->group(group);
  app.add_option("--tolerances-per-decade", o.per_decade, "Tolerances per decade of --tolerances")
      ->capture_default_str()->group(group);
}

const std::string kSolverGroup = "Reference and SUNDIALS";

void add_reference(CLI::App& app, ReferenceOptions& o) {
  app.add_option("--reference", o.kind,
                 "exact | cvode | manufactured | extended | integrator:SPEC@DT (SPEC as --integrator, at the fixed step "
                 "DT [s]); extended: the ODE solved in double-double to ~1e-30 [default: exact when the case has a "
                 "closed form, else cvode; extended with --precision extended]")
      ->group(kSolverGroup);
  app.add_option("--precision", o.precision,
                 "double | extended: the arithmetic the levels are stepped and compared in (extended: double-double, "
                 "~32 digits, for the built-in Runge-Kutta methods and explicit tableau files)")
      ->capture_default_str()->group(kSolverGroup);
  app.add_option("--reference-rtol", o.rtol, "Relative tolerance of the CVODE reference")
      ->capture_default_str()->group(kSolverGroup);
}

void add_cvode(CLI::App& app, CvodeOptions& o) {
  app.add_option("--rtol", o.rtol, "CVODE relative tolerance (--integrator cvode)")->capture_default_str()->group(kSolverGroup);
  app.add_option("--atol", o.atol, "CVODE absolute tolerance per field = atol x the field's size [default: rtol]")
      ->group(kSolverGroup);
  app.add_option("--method", o.method, "CVODE method: adams | bdf")->capture_default_str()->group(kSolverGroup);
}

void add_solver(CLI::App& app, SolverOptions& o) {
  app.add_option("--linear-solver", o.linear_solver, "BDF linear solver: diag (CVDiag) | spgmr (matrix-free)")
      ->capture_default_str()->group(kSolverGroup);
  app.add_option("--max-steps", o.max_steps, "CVODE's most steps per solve")->capture_default_str()->group(kSolverGroup);
  app.add_option("--vector", o.vector, "SUNDIALS vector: serial | openmp")->capture_default_str()->group(kSolverGroup);
}

const std::string kExecGroup = "Your own integrator (--integrator exec:COMMAND, docs/exchange.md)";

void add_exec(CLI::App& app, ExecOptions& o) {
  app.add_option("--exec-order", o.order, "The nominal order of your integrator (0: not declared)")
      ->capture_default_str()->group(kExecGroup);
  app.add_option("--exec-timeout", o.timeout, "Seconds your program may take per level before it is killed")
      ->capture_default_str()->group(kExecGroup);
  app.add_flag("--exec-shell", o.shell, "Run COMMAND through /bin/sh -c (default: as an argument list, no shell)")
      ->group(kExecGroup);
}

const std::string kOutputGroup = "Outputs (written whole at the end, or not at all)";

}  // namespace

void add_outputs(CLI::App& app, OutputOptions& o, const char* what, const char* figure) {
  app.add_option("--json", o.json_file, std::string("Write the ") + what + " as JSON")->group(kOutputGroup);
  app.add_option("--csv", o.csv_file, std::string("Write the ") + what + " as CSV")->group(kOutputGroup);
  app.add_option("--table", o.table_file, "Write the console table to a file too")->group(kOutputGroup);
  app.add_option("--plot", o.plot_file, figure)->group(kOutputGroup);
  app.add_option("--title", o.title, "The figure's title [default: built from the results]")->group(kOutputGroup);
}

namespace {

// Not study options (to_json leaves them out): they say where the levels come from, not what they are.
void add_journal_start(CLI::App& app, bool& resume, bool& restart) {
  CLI::Option* resuming =
      app.add_flag("--resume", resume,
                   "Continue the study from its journal beside --json (kept when a signal stopped it), if there "
                   "is one; refused when an option or the build differs")
          ->group(kOutputGroup);
  app.add_flag("--restart", restart,
               "Discard the journal beside --json, if there is one, and start the study over")
      ->group(kOutputGroup)
      ->excludes(resuming);
}

// check --baseline (harness/constant_gate.hpp): the tolerance means nothing without a baseline.
void add_baseline(CLI::App& app, CheckOptions& o) {
  CLI::Option* baseline =
      app.add_option("--baseline", o.baseline,
                     "A converge or check JSON result of this study (same case, parameters, levels): fail when an "
                     "error constant C of e = C dt^P leaves its band")
          ->group("Check");
  app.add_option("--constant-tolerance", o.constant_tolerance, "Pass when |C − C_baseline| ≤ this × C_baseline")
      ->capture_default_str()
      ->needs(baseline)
      ->group("Check");
}

}  // namespace

void add_expect_order(CLI::App& app, std::optional<double>& order, std::map<std::string, double>& by_variable,
                      const std::string& help) {
  const auto expect = [&order, &by_variable](const std::vector<std::string>& values) {
    order.reset();
    by_variable.clear();
    for (const std::string& value : values) add_expected_order(order, by_variable, value);
  };
  app.add_option_function<std::vector<std::string>>("--expect-order", expect, help)
      ->allow_extra_args(false)  // one value per --expect-order
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("P|NAME=P")
      ->group("Check");
}

// ---- converge and check -----------------------------------------------------------------------

void add_options(CLI::App& app, ConvergeOptions& o) {
  add_head(app, o.config, o.integrator, "The integrator under test (listed below)", o.problem);
  add_problem_options(app, o.problem);
  add_levels(app, o.levels, o.threads, false);
  add_level_search(app, o.search);
  add_tolerances(app, o.tolerances);
  add_reference(app, o.reference);
  add_cvode(app, o.cvode);
  add_solver(app, o.solver);
  add_exec(app, o.exec);
  add_outputs(app, o.outputs, "study",
              "Draw error against dt with fitted and reference slopes (.png, .svg or .pdf)");
  app.add_option("--per-particle", o.per_particle_file,
                 "Write each particle's xi and finest-level error (CSV: where in the cloud the error lives)")
      ->group(kOutputGroup);
  app.add_flag("--plot-relative", o.plot_relative, "Plot relative L2 errors on one axis")->group(kOutputGroup);
  app.add_option("--history", o.history_file,
                 "Write the finest level's L2 norms, and the reference's size, at --history-outputs times (CSV)")
      ->group(kOutputGroup);
  app.add_option("--history-outputs", o.history_outputs, "How many output times the history has")
      ->capture_default_str()
      ->group(kOutputGroup);
  add_journal_start(app, o.resume, o.restart);
}

void add_options(CLI::App& app, CheckOptions& o) {
  add_options(app, static_cast<ConvergeOptions&>(o));
  add_expect_order(app, o.expect_order, o.expect_order_by_variable,
                   "Expected order of accuracy P (required, but with --tolerances); NAME=P, repeated, for a variable "
                   "of another order (an invariant one above the method)");
  app.add_option("--order-tolerance", o.order_tolerance, "Pass when |fitted order − P| ≤ this")
      ->capture_default_str()
      ->group("Check");
  app.add_flag("--no-escalate", o.no_escalate,
               "Judge the study as it ran: a check that cannot decide is not run again with finer levels, or in "
               "extended precision where double's floors came first, one level more until it decides (the default)")
      ->group("Check");
  add_baseline(app, o);
  app.add_option("--expect-proportionality", o.expect_proportionality,
                 "With --tolerances: the expected exponent E of error ≈ C rtol^E")
      ->capture_default_str()
      ->group("Check");
  app.add_option("--proportionality-tolerance", o.proportionality_tolerance,
                 "With --tolerances: pass when |fitted exponent − E| ≤ this")
      ->capture_default_str()
      ->group("Check");
  app.add_option("--junit", o.junit_file,
                 "Write each variable's verdict as JUnit XML, the test report CI systems show (- for standard output)")
      ->group(kOutputGroup);
  app.add_option("--html", o.html_file,
                 "Write the study as one self-contained HTML page: verdict, figure, levels, reference, provenance")
      ->group(kOutputGroup);
  app.add_option("--summary", o.summary_file,
                 "Write the verdicts as Markdown, failures first, for $GITHUB_STEP_SUMMARY or a merge-request comment "
                 "(- for standard output)")
      ->group(kOutputGroup);
}

// ---- precision --------------------------------------------------------------------------------

void add_options(CLI::App& app, PrecisionOptions& o) {
  add_head(app, o.config, o.integrator, "Fixed-step method beside CVODE (listed below; not cvode)", o.problem);
  add_problem_options(app, o.problem);
  add_levels(app, o.levels, o.threads, true);
  add_reference(app, o.reference);
  add_solver(app, o.solver);
  const std::string sweep = "Sweep (CVODE Adams and BDF, atol = rtol x each field's size)";
  app.add_option("--rtol-max", o.rtol_max, "Loosest CVODE relative tolerance")->capture_default_str()->group(sweep);
  app.add_option("--rtol-min", o.rtol_min, "Tightest CVODE relative tolerance (the last point on the grid at or above it)")
      ->capture_default_str()->group(sweep);
  app.add_option("--per-decade", o.per_decade, "Tolerances per decade: rtol_i = rtol-max / 10^(i/per-decade)")
      ->capture_default_str()->group(sweep);
  add_outputs(app, o.outputs, "runs", "Draw the work-precision diagram (.png, .svg or .pdf)");
  add_journal_start(app, o.resume, o.restart);
}

// ---- sharpness --------------------------------------------------------------------------------

void add_options(CLI::App& app, SharpnessOptions& o) {
  app.add_option("--case", o.problem.case_name, "Verification case (listed below)")->capture_default_str();
  app.add_option("--integrator", o.integrator, "tableau:FILE, the Butcher tableau whose coefficients are perturbed")
      ->required();
  add_problem_options(app, o.problem);
  add_levels(app, o.levels, o.threads, false);
  add_reference(app, o.reference);
  add_solver(app, o.solver);
  const std::string group = "Sharpness";
  app.add_option("--delta", o.delta, "Perturbation: x -> x (1 + delta), a zero coefficient -> delta")
      ->capture_default_str()->group(group);
  app.add_option("--order-tolerance", o.order_tolerance, "A mutant is caught when |fitted order − its claimed order| > this")
      ->capture_default_str()->group(group);
  app.add_option("--constant-tolerance", o.constant_tolerance,
                 "A mutant is caught when |C − C_unperturbed| > this × C_unperturbed")
      ->capture_default_str()->group(group);
  app.add_option("--alternative-reference", o.alternative,
                 "The reference a perturbation the study misses is tried against: as --reference, or none")
      ->capture_default_str()->group(group);
  app.add_option("--json", o.json_file, "Write every perturbation and what caught it as JSON")->group(kOutputGroup);
}

}  // namespace dlpverify::cli
