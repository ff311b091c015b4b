#include "dlpverify/work_precision.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "dlpverify/study.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/progress.hpp"
#include "io/provenance.hpp"
#include "io/result_units.hpp"

namespace dlpverify {

namespace {

// A count the solver must report; a solver without it cannot be placed on the work axis.
long reported_count(const std::optional<long>& count, const char* key, const std::string& run) {
  if (!count) throw std::invalid_argument("work-precision run " + run + ": the solver reported no '" + key + "'");
  return *count;
}

}  // namespace

std::string run_label(const std::string& method, const std::optional<double>& rtol, const std::optional<double>& dt) {
  if (rtol) return method + printf_string(" at rtol %g", *rtol);
  if (dt) return method + printf_string(" at dt %g", *dt);
  return method;
}

namespace {

// One run: solved, timed, its work counted and its state measured against the reference.
PrecisionRunResult solve_run(const PrecisionRun& run, const State& reference, const std::vector<Variable>& variables) {
  const std::string label = run_label(run.method, run.rtol, run.dt);
  PrecisionRunResult r;
  r.method = run.method;
  r.rtol = run.rtol;
  r.dt = run.dt;

  State state;
  const auto start = std::chrono::steady_clock::now();
  try {
    state = run.solve(r.solver_statistics);
  } catch (const SolverError& e) {
    throw SolverError(label + ": " + e.what());
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (state.rows() != reference.rows() || state.cols() != reference.cols())
    throw std::invalid_argument("work-precision run " + label + ": returned " + std::to_string(state.rows()) +
                                " particles, the reference has " + std::to_string(reference.rows()));

  r.steps = reported_count(r.solver_statistics.steps, "steps", label);
  r.rhs_evals = reported_count(r.solver_statistics.rhs_evals, "rhs_evals", label) +
                r.solver_statistics.rhs_evals_jacobian.value_or(0);
  for (const Variable& variable : variables) r.norms.push_back(error_norms(state, reference, variable));
  return r;
}

// A run an earlier sweep finished must be this sweep's run i.
void check_done_run(const PrecisionRun& run, const PrecisionRunResult& done, std::size_t variables, std::size_t i) {
  if (done.method != run.method || done.rtol != run.rtol || done.dt != run.dt || done.norms.size() != variables)
    throw InputError("resumed run", run_label(done.method, done.rtol, done.dt),
                     "is not run " + std::to_string(i) + " (" + run_label(run.method, run.rtol, run.dt) + ") of this sweep");
}

}  // namespace

WorkPrecisionResult run_work_precision(const std::vector<PrecisionRun>& runs, const State& reference,
                                       const std::vector<double>& reference_error,
                                       const std::vector<Variable>& variables,
                                       const Progress<PrecisionRunResult>& progress) {
  WorkPrecisionResult result;
  result.variables = variables;
  result.reference_error = reference_error;
  result.reference_error.resize(variables.size(), 0.0);
  if (progress.done.size() > runs.size())
    throw InputError("resumed run", std::to_string(progress.done.size()), "more runs than this sweep has");

  // Runs taken over from a journal cost nothing: weight 0 in the estimate of the time left.
  std::vector<double> weights(runs.size(), 1.0);
  std::fill_n(weights.begin(), progress.done.size(), 0.0);
  dlpverify::progress::Task task("run", static_cast<long>(runs.size()), weights);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const bool done = i < progress.done.size();
    if (!done && progress.stop && progress.stop()) throw StudyStopped(static_cast<int>(i));
    PrecisionRunResult r = done ? progress.done[i] : solve_run(runs[i], reference, variables);
    if (done) check_done_run(runs[i], r, variables.size(), i);
    r.reference_margin.clear();
    r.reference_limited = false;
    for (std::size_t v = 0; v < variables.size(); ++v) {
      const double margin = result.reference_error[v] > 0.0 ? r.norms[v].l2 / result.reference_error[v]
                                                             : std::numeric_limits<double>::infinity();
      r.reference_margin.push_back(margin);
      r.reference_limited = r.reference_limited || margin < kMinimumReferenceMargin;
    }
    if (!done && progress.finished) progress.finished(r);
    result.runs.push_back(std::move(r));
    task.advance();
  }
  return result;
}

std::vector<double> tolerance_sweep(double rtol_max, double rtol_min, int per_decade) {
  if (!(rtol_max > 0.0) || !(rtol_min > 0.0) || rtol_min > rtol_max || per_decade < 1)
    throw std::invalid_argument("tolerance_sweep: needs 0 < rtol_min <= rtol_max and per_decade >= 1");
  const double points = std::floor(std::log10(rtol_max / rtol_min) * per_decade + 1e-9) + 1.0;
  std::vector<double> sweep;
  for (int i = 0; i < static_cast<int>(points); ++i) {
    const double rtol = rtol_max * std::pow(10.0, -static_cast<double>(i) / per_decade);
    sweep.push_back(std::stod(printf_string("%.12g", rtol)));
  }
  return sweep;
}

std::string format_table(const WorkPrecisionDescription& d, const WorkPrecisionResult& result) {
  std::ostringstream out;
  std::vector<std::string> methods;
  std::size_t method_width = 6;
  for (const auto& run : result.runs) {
    if (std::find(methods.begin(), methods.end(), run.method) == methods.end()) methods.push_back(run.method);
    method_width = std::max(method_width, run.method.size());
  }
  std::string method_list;
  for (const auto& m : methods) method_list += (method_list.empty() ? "" : ", ") + m;
  out << "case " << d.case_name << " · work-precision: " << method_list << " · reference " << d.reference << " ("
      << d.reference_detail << ")\n";
  const std::string unit = dimensionless(d.time_unit) ? "" : " " + d.time_unit;
  out << count_text(d.particles, d.member_nouns) << " · t0 = " << printf_string("%.6g", d.t0) << unit << " · t_end = "
      << printf_string("%.6g", d.t_end) << unit << " after t0\n\n";

  const int w = static_cast<int>(method_width);
  out << printf_string("%-*s %15s %8s %10s %10s", w, "method", "rtol / dt", "steps", "RHS evals", "wall s");
  for (const auto& v : result.variables)
    out << printf_string(" | %-14s %10s", ("L2 " + v.name).c_str(), "rel L2");
  out << "\n";
  bool any_limited = false;
  for (const auto& run : result.runs) {
    const std::string control = run.rtol ? printf_string("rtol %.3e", *run.rtol)
                                : run.dt ? printf_string("dt %.3e", *run.dt)
                                         : std::string("-");
    out << printf_string("%-*s %15s %8ld %10ld %10.3e", w, run.method.c_str(), control.c_str(), run.steps,
                         run.rhs_evals, run.wall_seconds);
    for (const auto& n : run.norms) out << printf_string(" | %-14.3e %10.3e", n.l2, n.relative);
    if (run.reference_limited) out << "  *";
    any_limited = any_limited || run.reference_limited;
    out << "\n";
  }

  bool header = false;
  for (std::size_t v = 0; v < result.variables.size(); ++v) {
    if (result.reference_error[v] <= 0.0) continue;
    if (!header) out << "\n";
    header = true;
    out << printf_string("%-12s reference error ~%.3e\n", result.variables[v].name.c_str(), result.reference_error[v]);
  }
  if (any_limited)
    out << "* within 100 x of the reference's own error: that run measures the reference, not the method\n";
  return out.str();
}

std::string format_csv(const WorkPrecisionDescription& d, const WorkPrecisionResult& result) {
  std::ostringstream out;
  out << csv_header("work-precision, case " + d.case_name + ", reference " + d.reference + ", " +
                         count_text(d.particles, d.member_nouns),
                     d.provenance, d.options);
  out << "method,rtol,dt,steps,rhs_evals,wall_s";
  for (const auto& v : result.variables)
    for (const char* column : {"l2", "rel_l2", "rms", "max"}) out << "," << column << "_" << v.name;
  out << ",reference_limited\n";
  for (const auto& run : result.runs) {
    out << run.method << "," << (run.rtol ? printf_string("%.17g", *run.rtol) : std::string()) << ","
        << (run.dt ? printf_string("%.17g", *run.dt) : std::string())
        << printf_string(",%ld,%ld,%.6g", run.steps, run.rhs_evals, run.wall_seconds);
    for (const auto& n : run.norms) out << printf_string(",%.17g,%.17g,%.17g,%.17g", n.l2, n.relative, n.rms, n.max);
    out << "," << (run.reference_limited ? "true" : "false") << "\n";
  }
  return out.str();
}

nlohmann::json to_json(const WorkPrecisionDescription& d, const WorkPrecisionResult& result) {
  using nlohmann::json;
  json j;
  j["case"] = d.case_name;
  j["reference"] = d.reference;
  j["reference_detail"] = d.reference_detail;
  j["particles"] = d.particles;
  j["member_noun"] = d.particles == 1 ? d.member_nouns.one : d.member_nouns.many;  // as the count reads
  j["t0"] = d.t0;
  j["t_end"] = d.t_end;
  j["time_unit"] = d.time_unit;
  j["variables"] = json::array();
  j["units"] = json::object();
  for (const auto& v : result.variables) {
    j["variables"].push_back(v.name);
    j["units"][v.name] = v.unit;
  }

  j["runs"] = json::array();
  for (const auto& run : result.runs) {
    json r;
    r["method"] = run.method;
    if (run.rtol) r["rtol"] = *run.rtol;
    if (run.dt) r["dt"] = *run.dt;
    r["steps"] = run.steps;
    r["rhs_evals"] = run.rhs_evals;
    r["wall_s"] = run.wall_seconds;
    for (std::size_t v = 0; v < result.variables.size(); ++v) {
      const auto& name = result.variables[v].name;
      const auto& n = run.norms[v];
      r["l2_" + name] = number_or_null(n.l2);
      r["rel_l2_" + name] = number_or_null(n.relative);
      r["norms_" + name] = {{"l2", number_or_null(n.l2)},
                            {"rms", number_or_null(n.rms)},
                            {"relative", number_or_null(n.relative)},
                            {"max", number_or_null(n.max)},
                            {"solution_l2", number_or_null(n.reference_l2)}};
    }
    r["reference_limited"] = run.reference_limited;
    if (!run.solver_statistics.empty()) r["solver_statistics"] = run.solver_statistics;
    j["runs"].push_back(r);
  }

  json reference_error = json::object();
  for (std::size_t v = 0; v < result.variables.size(); ++v)
    reference_error[result.variables[v].name] = result.reference_error[v] > 0.0 ? json(result.reference_error[v]) : json();
  j["reference_error"] = reference_error;
  if (!d.reference_statistics.empty()) j["reference_statistics"] = d.reference_statistics;
  j["options"] = d.options;
  j["provenance"] = d.provenance;
  return j;
}

}  // namespace dlpverify
