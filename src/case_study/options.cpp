#include "case_study/options.hpp"

#include <cmath>
#include <cstdlib>
#include <set>

#include <omp.h>

#include "dlpverify/errors.hpp"
#include "families/families.hpp"
#include "io/format.hpp"
#include "io/output_path.hpp"
#include "io/value_checks.hpp"

namespace dlpverify::case_study {

using families::problem_options_json;
using families::validate_problem_options;

// More threads than a few per core only share the cores, and libgomp puts each new thread's start
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

namespace {

nlohmann::json levels_json(const LevelOptions& o, int threads) {
  return {{"t-end", optional_json(o.t_end)},
          {"dt", optional_json(o.dt)},
          {"levels", o.auto_levels ? nlohmann::json("auto") : optional_json(o.levels)},
          {"ratio", o.ratio},
          {"threads", threads}};
}

// The options every study file holds: the case and its family's, the levels, the integrator, the
// reference and CVODE's solver, for the report (keys without their dashes).
nlohmann::json study_json(const std::string& config, const std::string& integrator, const ProblemOptions& problem,
                          const LevelOptions& levels, int threads, const ReferenceOptions& reference,
                          const SolverOptions& solver) {
  nlohmann::json j = problem_options_json(problem);
  j.update(levels_json(levels, threads));
  j.update({{"integrator", integrator},
            {"config", config},
            {"reference", optional_json(reference.kind)},
            {"reference-rtol", reference.rtol},
            {"precision", reference.precision},
            {"linear-solver", solver.linear_solver},
            {"max-steps", solver.max_steps},
            {"vector", solver.vector}});
  return j;
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

void validate_reference(const ReferenceOptions& o) {
  if (o.kind && *o.kind != "exact" && *o.kind != "cvode" && *o.kind != "manufactured" && *o.kind != "extended" &&
      !integrator_reference_option(*o.kind))
    throw InputError("--reference", *o.kind, "must be exact, cvode, manufactured, extended or integrator:SPEC@DT");
  if (o.precision != "double" && o.precision != "extended")
    throw InputError("--precision", o.precision, "must be double or extended");
}

void validate_cvode(const CvodeOptions& o) {
  require_tolerance("--rtol", o.rtol);  // what double precision can honour; CVODE takes any in (0, 1)
  if (o.atol) require_positive("--atol", *o.atol);
  if (o.method != "adams" && o.method != "bdf") throw InputError("--method", o.method, "must be adams or bdf");
}

void validate_solver(const SolverOptions& o) {
  if (o.linear_solver != "diag" && o.linear_solver != "spgmr")
    throw InputError("--linear-solver", o.linear_solver, "must be diag or spgmr");
  if (o.vector != "serial" && o.vector != "openmp") throw InputError("--vector", o.vector, "must be serial or openmp");
}

}  // namespace

JournalStart journal_start(bool resume, bool restart) {
  return resume ? JournalStart::resume : restart ? JournalStart::restart : JournalStart::fresh;
}

JournalTerms journal_terms() { return {"--json", "--resume", "--restart", "option --", {}, {}}; }

nlohmann::json outputs_json(const OutputOptions& o) {
  return {{"json", o.json_file}, {"csv", o.csv_file}, {"table", o.table_file}, {"plot", o.plot_file}, {"title", o.title}};
}

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

std::vector<std::pair<std::string, std::string>> output_files(const CheckOptions& o) {
  std::vector<std::pair<std::string, std::string>> files = output_files(static_cast<const ConvergeOptions&>(o));
  files.emplace_back("--junit", o.junit_file);
  files.emplace_back("--html", o.html_file);
  files.emplace_back("--summary", o.summary_file);
  return files;
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

void add_expected_order(std::optional<double>& order_of_all, std::map<std::string, double>& by_variable,
                        const std::string& value) {
  const std::string::size_type equals = value.find('=');
  const std::string name = equals == std::string::npos ? "" : value.substr(0, equals);
  const std::string order = equals == std::string::npos ? value : value.substr(equals + 1);
  char* end = nullptr;
  const double p = order.empty() ? std::nan("") : std::strtod(order.c_str(), &end);
  if ((equals != std::string::npos && name.empty()) || order.empty() || end != order.c_str() + order.size())
    throw InputError("--expect-order", value, "must be an order P, or NAME=P for a variable of its own order");
  if (!std::isfinite(p) || p <= 0.0) throw InputError("--expect-order", value, "must be positive and finite");
  if (name.empty())
    order_of_all = p;
  else
    by_variable[name] = p;
}

nlohmann::json expected_orders_json(const std::optional<double>& order, const std::map<std::string, double>& by_variable) {
  if (by_variable.empty()) return optional_json(order);
  nlohmann::json values = nlohmann::json::array();
  if (order) values.push_back(value_text(*order));
  for (const auto& [name, p] : by_variable) values.push_back(name + "=" + value_text(p));
  return values;
}

void validate(const CheckOptions& o) {
  validate(static_cast<const ConvergeOptions&>(o));
  if (!o.expect_order && !o.tolerances.range)
    throw InputError("--expect-order", "", "is required (but with --tolerances)");
  if (o.tolerances.range && !o.expect_order_by_variable.empty())
    throw InputError("--expect-order", o.expect_order_by_variable.begin()->first + "=" +
                                           value_text(o.expect_order_by_variable.begin()->second),
                     "a study by --tolerances is judged by --expect-proportionality");
  if (o.expect_order) require_positive("--expect-order", *o.expect_order);
  require_positive("--order-tolerance", o.order_tolerance);
  require_fraction("--constant-tolerance", o.constant_tolerance);
  validate_outputs(output_files(o), o.config);
  if (o.tolerances.range && !o.html_file.empty())
    throw InputError("--html", o.html_file, "is written by a study at levels; --tolerances writes --json, --table, --plot, --junit and --summary");
  for (const auto& [option, path] : output_files(o))
    if (!o.baseline.empty() && path == o.baseline) throw InputError(option, path, "would overwrite the baseline --baseline");
  require_positive("--expect-proportionality", o.expect_proportionality);
  require_positive("--proportionality-tolerance", o.proportionality_tolerance);
}

nlohmann::json to_json(const ConvergeOptions& o) {
  nlohmann::json j = study_json(o.config, o.integrator, o.problem, o.levels, o.threads, o.reference, o.solver);
  j.update(outputs_json(o.outputs));
  j.update({{"rtol", o.cvode.rtol},              {"atol", optional_json(o.cvode.atol)},
            {"method", o.cvode.method},
            {"plot-relative", o.plot_relative},  {"per-particle", o.per_particle_file},
            {"history", o.history_file},         {"history-outputs", o.history_outputs},
            {"exec-order", o.exec.order},        {"exec-timeout", o.exec.timeout}, {"exec-shell", o.exec.shell}});
  j.update({{"budget", o.search.budget}, {"order-ci", o.search.order_ci}});
  j.update({{"tolerances", optional_json(o.tolerances.range)}, {"tolerances-per-decade", o.tolerances.per_decade}});
  return j;
}

nlohmann::json to_json(const CheckOptions& o) {
  nlohmann::json j = to_json(static_cast<const ConvergeOptions&>(o));
  j["expect-order"] = expected_orders_json(o.expect_order, o.expect_order_by_variable);
  j["order-tolerance"] = o.order_tolerance;
  j["no-escalate"] = o.no_escalate;
  j["baseline"] = o.baseline;
  j["constant-tolerance"] = o.constant_tolerance;
  j["expect-proportionality"] = o.expect_proportionality;
  j["proportionality-tolerance"] = o.proportionality_tolerance;
  j["junit"] = o.junit_file;
  j["html"] = o.html_file;
  j["summary"] = o.summary_file;
  return j;
}

// ---- precision --------------------------------------------------------------------------------

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
  nlohmann::json j = study_json(o.config, o.integrator, o.problem, o.levels, o.threads, o.reference, o.solver);
  j.update(outputs_json(o.outputs));
  j.update({{"rtol-max", o.rtol_max}, {"rtol-min", o.rtol_min}, {"per-decade", o.per_decade}});
  return j;
}


// ---- sharpness --------------------------------------------------------------------------------

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

}  // namespace dlpverify::case_study
