// A study of a named case, as the command line and a study file (--config) describe it: the options
// of `dlpverify converge`, `check`, `precision` and `sharpness`, each with its documented default,
// in groups that each command composes (a command binds only the options that mean something to
// it: no silently ignored flags). This room's errors name a value by its option, the study file's
// key with two dashes, since that is the name the user gave it.
//   converge   problem, levels, reference, CVODE tolerances and solver, outputs, history/per-particle
//   check      converge's, plus --expect-order and --order-tolerance
//   precision  problem, levels, reference, CVODE solver (not its tolerances: it sweeps them), the
//              sweep --rtol-max, --rtol-min, --per-decade, outputs
// Options left unset take the case's defaults (t-end, dt, levels).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/level_search.hpp"
#include "harness/constant_gate.hpp"
#include "integrators/exec/exec_integrator.hpp"
#include "families/problem_options.hpp"
#include "study/journal.hpp"
#include "integrators/sundials/cvode_integrator.hpp"

namespace dlpverify::case_study {

using families::GasOptions;
using families::ProblemOptions;
using families::ThermalOptions;

// The levels of docs/model.md §6; unset: the case's defaults.
struct LevelOptions {
  std::optional<double> t_end;
  std::optional<double> dt;
  std::optional<int> levels;
  double ratio = 2.0;
  bool auto_levels = false;  // --levels auto: the study finds its levels (dlpverify/level_search.hpp)
};

// The level search of --levels auto (converge and check only).
struct LevelSearchOptions {
  double budget = LevelSearchRules{}.budget_seconds;    // --budget [s]
  double order_ci = LevelSearchRules{}.order_half_width;  // --order-ci: target half-width of the fitted order's 95% interval
};

// --tolerances MAX:MIN: an adaptive integrator run once per rtol instead of at levels
// (dlpverify/tolerance_study.hpp), --tolerances-per-decade runs a decade.
struct ToleranceOptions {
  std::optional<std::string> range;  // "MAX:MIN" as given
  int per_decade = 1;
  double rtol_max = 0.0, rtol_min = 0.0;  // parsed from range by validate
};

// The case's closed form, or CVODE where there is none (docs/model.md §4); or any integrator at
// a fixed step, or a manufactured solution (docs/verification.md, "The reference").
struct ReferenceOptions {
  // exact | cvode | manufactured | integrator:SPEC@DT; default: exact when the case has a closed form
  std::optional<std::string> kind;
  double rtol = 1e-12;
  // The arithmetic of the levels and the reference: double | extended (double-double; its default
  // reference is extended, the ODE solved to ε_Extended)
  std::string precision = "double";
};

// --reference integrator:SPEC@DT: the integrator's name and its fixed step.
struct IntegratorReferenceOption {
  std::string integrator;  // SPEC, as --integrator takes it (it may hold ':' of its own)
  double dt = 0.0;         // DT, positive and finite
};
// The integrator reference `kind` names, split at its last '@'; nullopt for any other kind.
// Throws InputError naming --reference and the value when SPEC is empty or DT is not a positive
// finite number.
std::optional<IntegratorReferenceOption> integrator_reference_option(const std::string& kind);

// CVODE as the integrator under test (--integrator cvode): its tolerances and method.
struct CvodeOptions {
  double rtol = 1e-10;
  std::optional<double> atol;          // per field = atol × the field's scale; default rtol
  std::string method = "adams";        // adams | bdf
};

// CVODE's solver, for the method under test and the reference alike.
struct SolverOptions {
  std::string linear_solver = "diag";  // BDF's Newton iteration: diag (CVDiag) | spgmr (matrix-free)
  long max_steps = 100000;
  std::string vector = "serial";       // serial | openmp N_Vector
};

// Files written whole at the end, or not at all.
struct OutputOptions {
  std::string json_file, csv_file, table_file;
  std::string plot_file;  // the figure: error against Δt, or the work-precision diagram
  std::string title;      // the figure's title; empty: built from the results
};

// --json, --csv, --table, --plot and --title with their values, for the report.
nlohmann::json outputs_json(const OutputOptions& options);

// An external integrator (--integrator exec:COMMAND, docs/exchange.md).
struct ExecOptions {
  int order = 0;           // the declared nominal order; 0: not declared
  double timeout = 3600.0; // per level [s]
  bool shell = false;      // run COMMAND through /bin/sh -c
};

struct ConvergeOptions {
  std::string config;  // the study file, read before parsing (see study_file.hpp)
  std::string integrator = "rk2";
  int threads = 0;  // 0: OpenMP's default
  ProblemOptions problem;
  LevelOptions levels;
  LevelSearchOptions search;
  ToleranceOptions tolerances;
  ReferenceOptions reference;
  CvodeOptions cvode;
  SolverOptions solver;
  ExecOptions exec;
  OutputOptions outputs;
  std::string per_particle_file;  // the finest level's error of every member
  std::string history_file;       // the finest level's L2 norms over time
  int history_outputs = 50;
  bool plot_relative = false;     // error against Δt as relative L2 norms on one axis
  bool resume = false;            // continue from the journal beside --json; not a study option (not in to_json)
  bool restart = false;           // discard that journal and start over; not a study option either
};

struct CheckOptions : ConvergeOptions {
  std::optional<double> expect_order;  // required, but with --tolerances
  std::map<std::string, double> expect_order_by_variable;  // --expect-order NAME=P: a variable's own
  double order_tolerance = 0.1;
  bool no_escalate = false;            // an inconclusive check in double is not run again in extended precision
  std::string baseline;                // a JSON result of this study: gate on its error constants
  double constant_tolerance = kDefaultConstantTolerance;  // relative band around the baseline's C
  double expect_proportionality = 1.0;     // --tolerances: the exponent E of e ≈ C rtol^E
  double proportionality_tolerance = 0.25;  // pass when |E_fitted − E| ≤ this
  std::string junit_file;                   // --junit: each variable's verdict as JUnit XML (io/junit_xml.hpp)
  std::string html_file;                    // --html: the study as a self-contained page (case_study/html_report.hpp)
  std::string summary_file;                 // --summary: the verdicts as Markdown (case_study/summary.hpp)
};

struct PrecisionOptions {
  std::string config;
  std::string integrator = "rk2";  // the fixed-step method beside CVODE
  int threads = 0;
  ProblemOptions problem;
  LevelOptions levels;
  // The reference stays 100× below the sweep's tightest rtol (1e-12).
  ReferenceOptions reference{std::nullopt, 1e-14};
  SolverOptions solver;
  OutputOptions outputs;
  // CVODE's rtol sweeps rtol_max, rtol_max/10^(1/per_decade), … down to rtol_min
  double rtol_max = 1e-3;
  double rtol_min = 1e-12;
  int per_decade = 1;
  bool resume = false;   // as ConvergeOptions::resume
  bool restart = false;  // as ConvergeOptions::restart
};

// `dlpverify sharpness` (integrators/tableau/sharpness.hpp): a tableau's coefficients perturbed one
// at a time, each mutant studied on the case; a smaller cloud by default, for a quick run.
struct SharpnessOptions {
  SharpnessOptions() { problem.outer = 10; }
  std::string integrator;  // tableau:FILE (required)
  int threads = 0;
  ProblemOptions problem;
  LevelOptions levels;
  ReferenceOptions reference;
  SolverOptions solver;
  double delta = 1e-2;
  double order_tolerance = 0.1;
  double constant_tolerance = kDefaultConstantTolerance;
  std::string alternative = "manufactured";  // the reference a missed perturbation is tried on; none: not tried
  std::string json_file;
};

// Reject any value outside its domain with InputError naming the option and the value.
void validate(const ConvergeOptions& options);
void validate(const CheckOptions& options);
void validate(const PrecisionOptions& options);
void validate(const SharpnessOptions& options);

// One --expect-order value: P into `order`, the order of every variable, or NAME=P into
// `by_variable`, one variable's own; a later value for the same takes its place. InputError
// naming --expect-order and the value for anything else.
void add_expected_order(std::optional<double>& order, std::map<std::string, double>& by_variable,
                        const std::string& value);

// The --expect-order values for the report: P as a number, or, when a variable has its own, every
// value as given ("2", "energy=3").
nlohmann::json expected_orders_json(const std::optional<double>& order, const std::map<std::string, double>& by_variable);

// --tolerances MAX:MIN into rtol_max and rtol_min (InputError naming the option and the value).
void parse_tolerance_range(ToleranceOptions& options);

// Every option and its value, for the report (after case defaults are filled in).
nlohmann::json to_json(const ConvergeOptions& options);
nlohmann::json to_json(const CheckOptions& options);
nlohmann::json to_json(const PrecisionOptions& options);
nlohmann::json to_json(const SharpnessOptions& options);

// The CVODE settings the options ask for (--rtol, --method; --linear-solver, --max-steps, --vector).
CvodeSettings cvode_settings(const CvodeOptions& tolerances, const SolverOptions& solver);

// The exec:COMMAND integrator's settings (--exec-order, --exec-timeout, --exec-shell, --threads).
exchange::ExecSettings exec_settings(const ConvergeOptions& options);

// Each file output with its option name, for the path checks ({"--json", path}, …).
std::vector<std::pair<std::string, std::string>> output_files(const ConvergeOptions& options);
std::vector<std::pair<std::string, std::string>> output_files(const CheckOptions& options);  // converge's, --junit, --html, --summary
std::vector<std::pair<std::string, std::string>> output_files(const PrecisionOptions& options);

// Refuses two outputs on one path (they would overwrite each other; on standard output,
// interleave) and an output on the study file `config`; /dev/null takes any number.
void validate_outputs(const std::vector<std::pair<std::string, std::string>>& files, const std::string& config);

// Whether an output option asks for its output: given, and not /dev/null, which discards an
// output before it is produced (no figure drawn, no history run).
bool wanted(const std::string& path);
// Whether an output goes to standard output (`-`, /dev/stdout): the console table then does not.
bool any_on_standard_output(const std::vector<std::pair<std::string, std::string>>& files);

// InputError naming --threads unless 0 (OpenMP's default, if that is within the bound) or at most
// 4 threads a core: more only share the cores, and libgomp's start of a team of 100,000 threads
// overflows the stack.
void validate_threads(int threads);

// The journal's start as --resume and --restart ask it, and its messages in the options' names.
JournalStart journal_start(bool resume, bool restart);
JournalTerms journal_terms();

}  // namespace dlpverify::case_study
