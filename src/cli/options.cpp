#include "cli/options.hpp"

#include <cmath>
#include <cstdlib>
#include <set>

#include <omp.h>

#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "io/value_checks.hpp"
#include "cli/problems.hpp"
#include "io/format.hpp"
#include "io/output_path.hpp"

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

// More threads than a few per core only share the cores; and libgomp puts each new thread's start
// data on the stack of the thread that starts the team (gomp_alloca in team.c, ~100 bytes a
// thread), so 100000 threads overflow an 8 MiB stack: a segfault, not an error message. 0 means
// OpenMP's default, which OMP_NUM_THREADS may also set too high.
void validate_threads(int threads) {
  const int cores = omp_get_num_procs(), most = 4 * cores;
  const std::string bound = "4 x the " + std::to_string(cores) + " cores = " + std::to_string(most);
  if (threads < 0) throw InputError("--threads", std::to_string(threads), "must be zero (all cores) or positive");
  if (threads > most) throw InputError("--threads", std::to_string(threads), "must be at most " + bound);
  if (threads == 0 && omp_get_max_threads() > most)
    throw InputError("--threads", "0", "OMP_NUM_THREADS asks for " + std::to_string(omp_get_max_threads()) +
                                           " threads, more than " + bound + "; give --threads");
}

nlohmann::json levels_json(const LevelOptions& o, int threads) {
  return {{"t-end", optional_json(o.t_end)},
          {"dt", optional_json(o.dt)},
          {"levels", o.auto_levels ? nlohmann::json("auto") : optional_json(o.levels)},
          {"ratio", o.ratio},
          {"threads", threads}};
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

// "MAX:MIN" into rtol_max ≥ rtol_min, both valid tolerances.
void parse_tolerances(ToleranceOptions& o) {
  if (!o.range) return;
  const std::string& text = *o.range;
  const std::string::size_type colon = text.find(':');
  char *end_max = nullptr, *end_min = nullptr;
  const std::string max = colon == std::string::npos ? "" : text.substr(0, colon);
  const std::string min = colon == std::string::npos ? "" : text.substr(colon + 1);
  o.rtol_max = max.empty() ? std::nan("") : std::strtod(max.c_str(), &end_max);
  o.rtol_min = min.empty() ? std::nan("") : std::strtod(min.c_str(), &end_min);
  if (max.empty() || min.empty() || end_max != max.c_str() + max.size() || end_min != min.c_str() + min.size())
    throw InputError("--tolerances", text, "must be MAX:MIN, two relative tolerances");
  require_tolerance("--tolerances", o.rtol_max);
  require_tolerance("--tolerances", o.rtol_min);
  if (o.rtol_min >= o.rtol_max) throw InputError("--tolerances", text, "MIN must be below MAX");
  if (o.per_decade < 1 || o.per_decade > 20)
    throw InputError("--tolerances-per-decade", std::to_string(o.per_decade), "must lie in [1, 20]");
}

const std::string kSolverGroup = "Reference and SUNDIALS";

void add_reference(CLI::App& app, ReferenceOptions& o) {
  app.add_option("--reference", o.kind,
                 "exact | cvode | manufactured | integrator:SPEC@DT (SPEC as --integrator, at the fixed step DT [s]) "
                 "[default: exact when the case has a closed form, else cvode]")
      ->group(kSolverGroup);
  app.add_option("--reference-rtol", o.rtol, "Relative tolerance of the CVODE reference")
      ->capture_default_str()->group(kSolverGroup);
}

void validate_reference(const ReferenceOptions& o) {
  if (o.kind && *o.kind != "exact" && *o.kind != "cvode" && *o.kind != "manufactured" &&
      !integrator_reference_option(*o.kind))
    throw InputError("--reference", *o.kind, "must be exact, cvode, manufactured or integrator:SPEC@DT");
}

void add_cvode(CLI::App& app, CvodeOptions& o) {
  app.add_option("--rtol", o.rtol, "CVODE relative tolerance (--integrator cvode)")->capture_default_str()->group(kSolverGroup);
  app.add_option("--atol", o.atol, "CVODE absolute tolerance per field = atol x the field's size [default: rtol]")
      ->group(kSolverGroup);
  app.add_option("--method", o.method, "CVODE method: adams | bdf")->capture_default_str()->group(kSolverGroup);
}

void validate_cvode(const CvodeOptions& o) {
  require_tolerance("--rtol", o.rtol);  // what double precision can honour; CVODE takes any in (0, 1)
  if (o.atol) require_positive("--atol", *o.atol);
  if (o.method != "adams" && o.method != "bdf") throw InputError("--method", o.method, "must be adams or bdf");
}

void add_solver(CLI::App& app, SolverOptions& o) {
  app.add_option("--linear-solver", o.linear_solver, "BDF linear solver: diag (CVDiag) | spgmr (matrix-free)")
      ->capture_default_str()->group(kSolverGroup);
  app.add_option("--max-steps", o.max_steps, "CVODE's most steps per solve")->capture_default_str()->group(kSolverGroup);
  app.add_option("--vector", o.vector, "SUNDIALS vector: serial | openmp")->capture_default_str()->group(kSolverGroup);
}

void validate_solver(const SolverOptions& o) {
  if (o.linear_solver != "diag" && o.linear_solver != "spgmr")
    throw InputError("--linear-solver", o.linear_solver, "must be diag or spgmr");
  if (o.vector != "serial" && o.vector != "openmp") throw InputError("--vector", o.vector, "must be serial or openmp");
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

}  // namespace

JournalStart journal_start(bool resume, bool restart) {
  return resume ? JournalStart::resume : restart ? JournalStart::restart : JournalStart::fresh;
}

JournalTerms journal_terms() { return {"--json", "--resume", "--restart", "option --", {}}; }

nlohmann::json outputs_json(const OutputOptions& o) {
  return {{"json", o.json_file}, {"csv", o.csv_file}, {"table", o.table_file}, {"plot", o.plot_file}, {"title", o.title}};
}

namespace {

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

std::optional<IntegratorReferenceOption> integrator_reference_option(const std::string& kind) {
  const std::string prefix = "integrator:";
  if (kind.rfind(prefix, 0) != 0) return std::nullopt;
  const std::string::size_type at = kind.rfind('@');
  if (at == std::string::npos || at < prefix.size())
    throw InputError("--reference", kind, "must be integrator:SPEC@DT, the integrator and its fixed step DT [s]");
  IntegratorReferenceOption option;
  option.integrator = kind.substr(prefix.size(), at - prefix.size());
  if (option.integrator.empty()) throw InputError("--reference", kind, "names no integrator before '@'");
  const std::string dt = kind.substr(at + 1);
  char* end = nullptr;
  option.dt = dt.empty() ? std::nan("") : std::strtod(dt.c_str(), &end);
  if (dt.empty() || end != dt.c_str() + dt.size() || !std::isfinite(option.dt) || option.dt <= 0.0)
    throw InputError("--reference", kind, "its step DT = '" + dt + "' must be a positive finite number [s]");
  return option;
}

// Two outputs on one path would overwrite each other (on standard output: interleave); an
// output on the study file would lose it. /dev/null takes any number.
void validate_outputs(const std::vector<std::pair<std::string, std::string>>& files, const std::string& config) {
  std::set<std::string> seen;
  for (const auto& [option, path] : files) {
    if (!wanted(path)) continue;
    if (!config.empty() && path == config) throw InputError(option, path, "would overwrite the study file --config");
    const bool to_stdout = output_target(path) == OutputTarget::standard_output;
    if (!seen.insert(to_stdout ? "-" : path).second)
      throw InputError(option, path, to_stdout ? "standard output is also given for another output"
                                               : "is also given for another output");
  }
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
  app.add_option("--expect-order", o.expect_order, "Expected order of accuracy P (required, but with --tolerances)")
      ->group("Check");
  app.add_option("--order-tolerance", o.order_tolerance, "Pass when |fitted order − P| ≤ this")
      ->capture_default_str()
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
}

bool wanted(const std::string& path) { return !path.empty() && output_target(path) != OutputTarget::discard; }

bool any_on_standard_output(const std::vector<std::pair<std::string, std::string>>& files) {
  for (const auto& file : files)
    if (!file.second.empty() && output_target(file.second) == OutputTarget::standard_output) return true;
  return false;
}

std::vector<std::pair<std::string, std::string>> output_files(const ConvergeOptions& o) {
  return {{"--json", o.outputs.json_file},  {"--csv", o.outputs.csv_file},       {"--table", o.outputs.table_file},
          {"--per-particle", o.per_particle_file}, {"--history", o.history_file}, {"--plot", o.outputs.plot_file}};
}

void validate(const ConvergeOptions& o) {
  validate_problem_options(o.problem);
  if (o.history_outputs < 1 || o.history_outputs > 100000)
    throw InputError("--history-outputs", std::to_string(o.history_outputs), "must lie in [1, 100000]");
  validate_threads(o.threads);
  ToleranceOptions tolerances = o.tolerances;
  parse_tolerances(tolerances);
  if (o.tolerances.range && o.levels.auto_levels)
    throw InputError("--levels", "auto", "a study by --tolerances has no levels");
  if (o.tolerances.range && (o.resume || o.restart))
    throw InputError(o.resume ? "--resume" : "--restart", "on",
                     "a study by --tolerances keeps no journal: a stopped sweep starts over when run again");
  if (o.levels.auto_levels && o.resume)
    throw InputError("--resume", "on",
                     "--levels auto records no levels to continue (the search decides them as it goes): run it "
                     "again without --resume; a journal it left holds no level and is started over");
  validate_reference(o.reference);
  validate_cvode(o.cvode);
  validate_solver(o.solver);
  validate_outputs(output_files(o), o.config);
}

void validate(const CheckOptions& o) {
  validate(static_cast<const ConvergeOptions&>(o));
  if (!o.expect_order && !o.tolerances.range)
    throw InputError("--expect-order", "", "is required (but with --tolerances)");
  if (o.expect_order) require_positive("--expect-order", *o.expect_order);
  require_positive("--order-tolerance", o.order_tolerance);
  require_fraction("--constant-tolerance", o.constant_tolerance);
  for (const auto& [option, path] : output_files(o))
    if (!o.baseline.empty() && path == o.baseline) throw InputError(option, path, "would overwrite the baseline --baseline");
  require_positive("--expect-proportionality", o.expect_proportionality);
  require_positive("--proportionality-tolerance", o.proportionality_tolerance);
}

nlohmann::json to_json(const ConvergeOptions& o) {
  nlohmann::json j = problem_options_json(o.problem);
  j.update(levels_json(o.levels, o.threads));
  j.update(outputs_json(o.outputs));
  j.update({{"integrator", o.integrator},        {"config", o.config},
            {"reference", optional_json(o.reference.kind)}, {"reference-rtol", o.reference.rtol},
            {"rtol", o.cvode.rtol},              {"atol", optional_json(o.cvode.atol)},
            {"method", o.cvode.method},          {"linear-solver", o.solver.linear_solver},
            {"max-steps", o.solver.max_steps},   {"vector", o.solver.vector},
            {"plot-relative", o.plot_relative},  {"per-particle", o.per_particle_file},
            {"history", o.history_file},         {"history-outputs", o.history_outputs},
            {"exec-order", o.exec.order},        {"exec-timeout", o.exec.timeout}, {"exec-shell", o.exec.shell}});
  j.update({{"budget", o.search.budget}, {"order-ci", o.search.order_ci}});
  j.update({{"tolerances", optional_json(o.tolerances.range)}, {"tolerances-per-decade", o.tolerances.per_decade}});
  return j;
}

nlohmann::json to_json(const CheckOptions& o) {
  nlohmann::json j = to_json(static_cast<const ConvergeOptions&>(o));
  j["expect-order"] = optional_json(o.expect_order);
  j["order-tolerance"] = o.order_tolerance;
  j["baseline"] = o.baseline;
  j["constant-tolerance"] = o.constant_tolerance;
  j["expect-proportionality"] = o.expect_proportionality;
  j["proportionality-tolerance"] = o.proportionality_tolerance;
  return j;
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

std::vector<std::pair<std::string, std::string>> output_files(const PrecisionOptions& o) {
  return {{"--json", o.outputs.json_file}, {"--csv", o.outputs.csv_file}, {"--table", o.outputs.table_file},
          {"--plot", o.outputs.plot_file}};
}

void validate(const PrecisionOptions& o) {
  validate_problem_options(o.problem);
  validate_threads(o.threads);
  if (o.levels.auto_levels)
    throw InputError("--levels", "auto", "precision runs the fixed-step method at given levels: give a number");
  validate_reference(o.reference);
  validate_solver(o.solver);
  require_tolerance("--rtol-max", o.rtol_max);
  require_tolerance("--rtol-min", o.rtol_min);
  if (o.rtol_min > o.rtol_max)
    throw InputError("--rtol-min", value_text(o.rtol_min), "is larger than --rtol-max = " + value_text(o.rtol_max));
  if (o.per_decade < 1) throw InputError("--per-decade", std::to_string(o.per_decade), "must be at least 1");
  if (o.per_decade > 20) throw InputError("--per-decade", std::to_string(o.per_decade), "must be at most 20");
  validate_outputs(output_files(o), o.config);
}

void parse_tolerance_range(ToleranceOptions& o) { parse_tolerances(o); }

nlohmann::json to_json(const PrecisionOptions& o) {
  nlohmann::json j = problem_options_json(o.problem);
  j.update(levels_json(o.levels, o.threads));
  j.update(outputs_json(o.outputs));
  j.update({{"integrator", o.integrator},      {"config", o.config},
            {"reference", optional_json(o.reference.kind)}, {"reference-rtol", o.reference.rtol},
            {"linear-solver", o.solver.linear_solver}, {"max-steps", o.solver.max_steps},
            {"vector", o.solver.vector},       {"rtol-max", o.rtol_max},
            {"rtol-min", o.rtol_min},          {"per-decade", o.per_decade}});
  return j;
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

void validate(const SharpnessOptions& o) {
  validate_problem_options(o.problem);
  validate_threads(o.threads);
  validate_reference(o.reference);
  validate_solver(o.solver);
  if (!std::isfinite(o.delta) || o.delta <= 0.0 || o.delta > 0.5)
    throw InputError("--delta", value_text(o.delta), "must lie in (0, 0.5]");
  require_positive("--order-tolerance", o.order_tolerance);
  require_fraction("--constant-tolerance", o.constant_tolerance);
  if (o.alternative != "none") {
    try {
      validate_reference(ReferenceOptions{o.alternative, o.reference.rtol});
    } catch (const InputError&) {
      throw InputError("--alternative-reference", o.alternative, "must be none, exact, cvode, manufactured or integrator:SPEC@DT");
    }
  }
}

nlohmann::json to_json(const SharpnessOptions& o) {
  nlohmann::json j = problem_options_json(o.problem);
  j.update(levels_json(o.levels, o.threads));
  j.update({{"integrator", o.integrator},         {"reference", optional_json(o.reference.kind)},
            {"reference-rtol", o.reference.rtol}, {"linear-solver", o.solver.linear_solver},
            {"max-steps", o.solver.max_steps},    {"vector", o.solver.vector},
            {"delta", o.delta},                   {"order-tolerance", o.order_tolerance},
            {"constant-tolerance", o.constant_tolerance}, {"alternative-reference", o.alternative},
            {"json", o.json_file}});
  return j;
}

exchange::ExecSettings exec_settings(const ConvergeOptions& o) {
  return {.command = "", .order = o.exec.order, .timeout_seconds = o.exec.timeout, .shell = o.exec.shell,
          .threads = o.threads > 0 ? o.threads : omp_get_max_threads()};
}

CvodeSettings cvode_settings(const CvodeOptions& tolerances, const SolverOptions& solver) {
  CvodeSettings s;
  s.rtol = tolerances.rtol;
  s.method = tolerances.method == "bdf" ? CvodeMethod::bdf : CvodeMethod::adams;
  s.linear_solver = solver.linear_solver == "spgmr" ? CvodeLinearSolver::spgmr : CvodeLinearSolver::diagonal;
  s.max_steps = solver.max_steps;
  s.openmp_vector = solver.vector == "openmp";
  return s;
}

}  // namespace dlpverify::cli
