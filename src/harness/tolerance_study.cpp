#include "dlpverify/tolerance_study.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "io/format.hpp"

namespace dlpverify {

namespace {

// An exponent within this of 0 means the error does not follow the tolerance at all.
constexpr double kIgnoredExponent = 0.25;

// The fit of ln e against ln rtol over the runs the reference can judge (fit_order, rtol for Δt).
Proportionality proportionality(const ToleranceStudy& study, std::size_t v) {
  Proportionality p;
  std::vector<double> rtol, error;
  std::vector<int> used;
  for (std::size_t i = 0; i < study.runs.size(); ++i) {
    const ToleranceRunResult& run = study.runs[i];
    const double e = run.norms[v].relative;
    rtol.push_back(run.rtol);
    error.push_back(e);
    p.error_over_tolerance.push_back(e / run.rtol);
    if (std::isfinite(e) && e > 0.0 && run.reference_margin[v] >= kMinimumReferenceMargin)
      used.push_back(static_cast<int>(i));
  }
  for (std::size_t j = 1; j < used.size(); ++j)
    p.falls_steadily = p.falls_steadily && error[static_cast<std::size_t>(used[j])] < error[static_cast<std::size_t>(used[j - 1])];
  p.exponent = fit_order(rtol, error, used);
  return p;
}

std::string interval_text(const OrderFit& fit) {
  if (!fit.valid) return "no exponent";
  if (!std::isfinite(fit.ci_low)) return printf_string("exponent %.3f from two runs (no interval)", fit.value);
  return printf_string("exponent %.3f (95%% CI [%.3f, %.3f])", fit.value, fit.ci_low, fit.ci_high);
}

}  // namespace

ToleranceStudy run_tolerance_study(const std::vector<ToleranceRun>& runs, const State& reference,
                                   const std::vector<double>& reference_error, const std::vector<Variable>& variables) {
  ToleranceStudy study;
  study.variables = variables;
  study.reference_error = reference_error;
  study.reference_error.resize(variables.size(), 0.0);
  for (const ToleranceRun& run : runs) {
    ToleranceRunResult r;
    r.rtol = run.rtol;
    const State state = run.solve(r.solver_statistics);
    for (std::size_t v = 0; v < variables.size(); ++v) {
      r.norms.push_back(error_norms(state, reference, variables[v]));
      r.reference_margin.push_back(study.reference_error[v] > 0.0 ? r.norms.back().l2 / study.reference_error[v]
                                                                   : std::numeric_limits<double>::infinity());
    }
    study.runs.push_back(std::move(r));
  }
  for (std::size_t v = 0; v < variables.size(); ++v) study.proportionality.push_back(proportionality(study, v));
  return study;
}

CheckVerdict check_proportionality(const ToleranceStudy& study, double expected, double tolerance) {
  CheckVerdict verdict;
  verdict.expected_order = expected;
  verdict.tolerance = tolerance;
  for (std::size_t v = 0; v < study.variables.size(); ++v) {
    const std::string& name = study.variables[v].name;
    const Proportionality& p = study.proportionality[v];
    const std::size_t used = p.exponent.levels.size();
    std::string line;
    CheckOutcome outcome = CheckOutcome::order_within;
    if (used < 3 || !p.exponent.valid) {
      outcome = CheckOutcome::no_order;
      line = printf_string("FAIL, only %zu run(s) the reference can judge (needs 3): no exponent measured", used);
    } else if (std::abs(p.exponent.value) <= kIgnoredExponent) {
      outcome = CheckOutcome::order_miss;
      line = "FAIL, the error does not follow the tolerance (" + interval_text(p.exponent) +
             "): the integrator ignores its tolerance";
    } else {
      const bool within = std::abs(p.exponent.value - expected) <= tolerance;
      outcome = within ? CheckOutcome::order_within : CheckOutcome::order_miss;
      line = (within ? "pass, " : "FAIL, ") + interval_text(p.exponent) +
             printf_string(" %s %.3f +/- %.3f (over %zu runs)", within ? "within" : "outside", expected, tolerance, used) +
             (p.falls_steadily ? "" : "; the error does not fall at every tightening");
    }
    verdict.findings.push_back({v, name, Criterion::order, outcome, std::move(line)});
  }
  return verdict;
}

std::string format_tolerance_table(const std::string& header, const ToleranceStudy& study,
                                   const std::optional<CheckVerdict>& verdict) {
  bool implicit = false;  // some run solved implicit stages: its Newton and Krylov counts get columns
  for (const ToleranceRunResult& run : study.runs) implicit = implicit || run.solver_statistics.nonlinear_iterations;
  std::ostringstream out;
  out << header << "\n\n" << printf_string("%10s %9s %9s %8s", "rtol", "steps", "rhs", "rejected");
  if (implicit) out << printf_string(" %8s %7s %8s %7s", "newton", "nl-fail", "krylov", "l-fail");
  for (const Variable& v : study.variables) out << printf_string(" | %-14s %9s", ("rel " + v.name).c_str(), "e/rtol");
  out << "\n";
  const auto count = [](const std::optional<long>& n) { return n ? std::to_string(*n) : std::string("-"); };
  for (std::size_t i = 0; i < study.runs.size(); ++i) {
    const ToleranceRunResult& run = study.runs[i];
    const SolverStatistics& s = run.solver_statistics;
    out << printf_string("%10.3e %9s %9s %8s", run.rtol, count(s.steps).c_str(), count(s.rhs_evals).c_str(),
                         count(s.error_test_failures).c_str());
    if (implicit)
      out << printf_string(" %8s %7s %8s %7s", count(s.nonlinear_iterations).c_str(),
                           count(s.nonlinear_convergence_failures).c_str(), count(s.linear_iterations).c_str(),
                           count(s.extra_count("linear_convergence_failures")).c_str());
    for (std::size_t v = 0; v < study.variables.size(); ++v)
      out << printf_string(" | %-14.3e %9.3g", run.norms[v].relative, study.proportionality[v].error_over_tolerance[i]);
    out << "\n";
  }
  out << "\n";
  for (std::size_t v = 0; v < study.variables.size(); ++v) {
    const Proportionality& p = study.proportionality[v];
    out << printf_string("%-12s ", study.variables[v].name.c_str()) << interval_text(p.exponent) << " of e against rtol over "
        << p.exponent.levels.size() << " runs; " << (p.falls_steadily ? "falls at every tightening" : "does NOT fall steadily")
        << "\n";
  }
  if (verdict) {
    out << "\ncheck: expected proportionality exponent " << printf_string("%g ± %g", verdict->expected_order, verdict->tolerance)
        << "\n";
    for (const std::string& line : verdict->lines()) out << "  " << line << "\n";
    out << (verdict->passed() ? "PASSED\n" : verdict->inconclusive() ? "INCONCLUSIVE\n" : "FAILED\n");
  }
  return out.str();
}

nlohmann::json to_json(const ToleranceStudy& study, const std::optional<CheckVerdict>& verdict) {
  using nlohmann::json;
  json runs = json::array();
  for (std::size_t i = 0; i < study.runs.size(); ++i) {
    const ToleranceRunResult& run = study.runs[i];
    json r = {{"rtol", run.rtol}, {"solver_statistics", run.solver_statistics}};
    const SolverStatistics& s = run.solver_statistics;
    r["steps"] = s.steps ? json(*s.steps) : json();
    r["rhs_evals"] = s.rhs_evals ? json(*s.rhs_evals) : json();
    r["rejected_steps"] = s.error_test_failures ? json(*s.error_test_failures) : json();
    // The implicit stages' solver work; null for an explicit method.
    const std::optional<long> linear_failures = s.extra_count("linear_convergence_failures");
    r["nonlinear_iterations"] = s.nonlinear_iterations ? json(*s.nonlinear_iterations) : json();
    r["nonlinear_convergence_failures"] = s.nonlinear_convergence_failures ? json(*s.nonlinear_convergence_failures) : json();
    r["linear_iterations"] = s.linear_iterations ? json(*s.linear_iterations) : json();
    r["linear_convergence_failures"] = linear_failures ? json(*linear_failures) : json();
    r["rhs_evals_jacobian"] = s.rhs_evals_jacobian ? json(*s.rhs_evals_jacobian) : json();
    for (std::size_t v = 0; v < study.variables.size(); ++v) {
      const std::string& name = study.variables[v].name;
      r["relative_" + name] = number_or_null(run.norms[v].relative);
      r["l2_" + name] = number_or_null(run.norms[v].l2);
      r["error_over_tolerance_" + name] = number_or_null(study.proportionality[v].error_over_tolerance[i]);
      r["reference_margin_" + name] = number_or_null(run.reference_margin[v]);
    }
    runs.push_back(r);
  }
  json by_variable = json::object();
  for (std::size_t v = 0; v < study.variables.size(); ++v) {
    const OrderFit& fit = study.proportionality[v].exponent;
    by_variable[study.variables[v].name] = {
        {"exponent", fit.valid ? json(fit.value) : json()},
        {"stderr", fit.valid ? number_or_null(fit.stderr_) : json()},
        {"ci95", fit.valid && std::isfinite(fit.ci_low) ? json::array({fit.ci_low, fit.ci_high}) : json()},
        {"runs_used", fit.levels},
        {"falls_steadily", study.proportionality[v].falls_steadily}};
  }
  json j = {{"runs", runs}, {"proportionality", by_variable}};
  if (verdict)
    j["check"] = {{"passed", verdict->passed()},
                  {"expected_proportionality", verdict->expected_order},
                  {"tolerance", verdict->tolerance},
                  {"findings", verdict->lines()}};
  return j;
}

}  // namespace dlpverify
