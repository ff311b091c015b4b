#include "dlpverify/report.hpp"

#include "io/provenance.hpp"
#include "io/format.hpp"
#include "io/printable.hpp"
#include "io/result_units.hpp"

#include <cmath>
#include <optional>
#include <cstdio>
#include <sstream>

namespace dlpverify {

namespace {

// The level's status in one word: the variables' statuses when they agree, "partly S" when the
// others are ok, "unstable" when any is.
std::string level_status(const StudyResult& study, int k) {
  std::optional<LevelStatus> other;
  bool any_ok = false, mixed = false;
  for (const auto& a : study.orders) {
    const LevelStatus s = a.status[static_cast<std::size_t>(k)];
    if (s == LevelStatus::unstable) return "unstable";
    if (s == LevelStatus::ok) {
      any_ok = true;
      continue;
    }
    mixed = mixed || (other && *other != s);
    other = s;
  }
  if (!other) return "ok";
  if (mixed) return "mixed";
  return (any_ok ? "partly " : "") + to_string(*other);
}

// The error constants of e ≈ C Δt^p, one line per variable that has one (dlpverify/error_constant.hpp);
// p the expected order, or the fitted order's integer when the fit names another (said so).
std::string constant_lines(const StudyResult& study) {
  std::string text;
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const ErrorConstant& c = study.orders[v].constant;
    if (!c.valid) continue;
    text += printf_string("%-12s error constant %.4e in e ≈ C dt^%g", study.plan.variables[v].name.c_str(), c.value, c.order);
    text += std::isfinite(c.ci_low) ? printf_string(" (95%% CI [%.4e, %.4e])", c.ci_low, c.ci_high) : " (no interval)";
    text += " over levels " + levels_text(c.levels);
    const double expected = expected_order_of(study.plan, v);
    if (c.order != expected)
      text += printf_string(", at order %g as fitted, not the expected %g", c.order, expected);
    text += "\n";
  }
  return text;
}

// `error_constant`: variable → {value, order, ci95, levels_used}, or null when it has none.
nlohmann::json constants_json(const StudyResult& study) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const ErrorConstant& c = study.orders[v].constant;
    j[study.plan.variables[v].name] =
        c.valid ? nlohmann::json{{"value", c.value},
                                 {"order", c.order},
                                 {"ci95", std::isfinite(c.ci_low) ? nlohmann::json::array({c.ci_low, c.ci_high})
                                                                  : nlohmann::json()},
                                 {"levels_used", c.levels}}
                : nlohmann::json();
  }
  return j;
}

}  // namespace

std::string format_table(const StudyDescription& d, const StudyResult& study, const std::optional<CheckVerdict>& verdict) {
  // A name the user or a file chose (a tableau file's path, an exec command, a label) shown as
  // stderr shows it: its line breaks too, which would otherwise forge a line of the table.
  const auto named = [](const std::string& name) { return printable(name, std::string_view::npos); };
  std::ostringstream out;
  out << "case " << named(d.case_name) << " · integrator " << named(d.integrator);
  if (d.integrator_order > 0) out << " (order " << d.integrator_order << ")";
  out << " · reference " << named(d.reference) << " (" << named(d.reference_detail) << ")\n";
  const std::string unit = dimensionless(d.time_unit) ? "" : " " + d.time_unit;
  out << count_text(d.particles, d.member_nouns) << " · t0 = " << printf_string("%.6g", d.t0) << unit << " · t_end = "
      << printf_string("%.6g", study.plan.t_end) << unit << " after t0 · ratio " << printf_string("%g", study.plan.ratio);
  if (study.plan.precision == Precision::extended) out << " · precision extended (double-double)";
  out << "\n\n";

  out << printf_string("%5s %10s %7s", "level", "dt", "steps");
  for (const auto& v : study.plan.variables) out << printf_string(" | %-14s %5s", ("L2 " + v.name).c_str(), "rate");
  out << " | status\n";
  for (const auto& level : study.levels) {
    out << printf_string("%5d %10.3e %7ld", level.level, level.dt, level.steps);
    for (std::size_t v = 0; v < study.orders.size(); ++v) {
      const auto& rate = study.orders[v].pairwise[level.level];
      out << printf_string(" | %-14.3e %5s", level.norms[v].l2, rate ? printf_string("%.2f", *rate).c_str() : "-");
    }
    out << " | " << level_status(study, level.level) << "\n";
  }
  out << "\n";

  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const auto& a = study.orders[v];
    const auto& name = study.plan.variables[v].name;
    if (a.exact_to_round_off)
      out << printf_string("%-12s exact to round-off at every level\n", name.c_str());
    else if (!a.fit.valid)
      out << printf_string("%-12s no fitted order: fewer than two levels in the asymptotic range\n", name.c_str());
    else if (std::isfinite(a.fit.stderr_))
      out << printf_string("%-12s fitted order %.3f ± %.3f s.e. (95%% CI [%.3f, %.3f]) over levels %s\n", name.c_str(),
                           a.fit.value, a.fit.stderr_, a.fit.ci_low, a.fit.ci_high, levels_text(a.fit.levels).c_str());
    else
      out << printf_string("%-12s fitted order %.3f from two levels %s (no interval)\n", name.c_str(), a.fit.value,
                           levels_text(a.fit.levels).c_str());
  }
  out << constant_lines(study);
  // Reference-free estimates (docs/model.md §6): what a user without a reference would conclude.
  for (std::size_t v = 0; v < study.self_convergence.size(); ++v) {
    const SelfConvergence& sc = study.self_convergence[v];
    if (!sc.order.back() || study.orders[v].status.back() == LevelStatus::round_off) continue;  // rounding noise
    out << printf_string("%-12s self-convergence order %.3f", study.plan.variables[v].name.c_str(), *sc.order.back());
    if (sc.richardson_error && study.against_next_level)  // no reference: no error was measured
      out << printf_string("; Richardson estimate of the finest error %.3e, GCI %.2e", *sc.richardson_error, *sc.gci);
    else if (sc.richardson_error)
      out << printf_string("; Richardson estimate of the finest error %.3e (measured %.3e), GCI %.2e",
                           *sc.richardson_error, study.levels.back().norms[v].l2, *sc.gci);
    out << "\n";
  }
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    if (study.reference.error[v] <= 0.0) continue;
    out << printf_string("%-12s reference error ~%.3e; finest level %.3g x larger%s\n",
                         study.plan.variables[v].name.c_str(), study.reference.error[v], study.reference.margin[v],
                         study.reference.margin[v] >= kMinimumReferenceMargin ? "" : "  << UNTRUSTWORTHY (needs 100 x)");
  }
  // Say why a level was left out of a fit.
  for (std::size_t v = 0; v < study.orders.size(); ++v)
    for (std::size_t k = 0; k < study.levels.size(); ++k)
      if (study.orders[v].status[k] != LevelStatus::ok)
        out << printf_string("  level %zu %s: %s — %s\n", k, study.plan.variables[v].name.c_str(),
                             to_string(study.orders[v].status[k]).c_str(), study.orders[v].rule[k].c_str());

  if (!d.diagnostics.empty()) {
    out << "\n" << named(d.case_name) << ":\n";
    for (const auto& [key, value] : d.diagnostics.items()) out << "  " << key << " = " << value.dump() << "\n";
  }
  if (verdict) {
    out << "\ncheck: expected order " << printf_string("%g ± %g", verdict->expected_order, verdict->tolerance);
    for (const auto& [name, order] : study.plan.expected_order_by_variable)
      out << printf_string(", %s %g", name.c_str(), order);
    out << "\n";
    for (const std::string& line : verdict->lines()) out << "  " << line << "\n";
    out << (verdict->passed() ? "PASSED\n" : verdict->inconclusive() ? "INCONCLUSIVE\n" : "FAILED\n");
  }
  return console_text(out.str());  // the control characters of any other name (a variable's)
}

std::string format_csv(const StudyDescription& d, const StudyResult& study) {
  std::ostringstream out;
  out << csv_header("convergence study, case " + d.case_name + ", integrator " + d.integrator + ", reference " +
                         d.reference + ", " + count_text(d.particles, d.member_nouns),
                     d.provenance, d.options);
  out << "level,dt,steps,wall_s";
  for (const auto& v : study.plan.variables)
    for (const char* column : {"l2", "rms", "rel", "max", "order", "status"}) out << "," << column << "_" << v.name;
  out << ",status\n";
  for (const auto& level : study.levels) {
    out << printf_string("%d,%.17g,%ld,%.6g", level.level, level.dt, level.steps, level.wall_seconds);
    for (std::size_t v = 0; v < study.orders.size(); ++v) {
      const auto& n = level.norms[v];
      const auto& rate = study.orders[v].pairwise[level.level];
      out << printf_string(",%.17g,%.17g,%.17g,%.17g,", n.l2, n.rms, n.relative, n.max)
          << (rate ? printf_string("%.17g", *rate) : std::string()) << "," << to_string(study.orders[v].status[level.level]);
    }
    out << "," << level_status(study, level.level) << "\n";
  }
  return out.str();
}

nlohmann::json study_identity(const StudyDescription& d, const StudyResult& study) {
  nlohmann::json j = {{"case", d.case_name}, {"reference", d.reference}, {"particles", d.particles}, {"t0", d.t0},
                      {"t_end", study.plan.t_end}, {"ratio", study.plan.ratio}, {"variables", nlohmann::json::array()},
                      {"parameters", d.parameters}};
  for (const auto& v : study.plan.variables) j["variables"].push_back(v.name);
  if (study.plan.precision == Precision::extended) j["precision"] = to_string(study.plan.precision);  // another study
  return j;
}

nlohmann::json to_json(const StudyDescription& d, const StudyResult& study, const std::optional<CheckVerdict>& verdict) {
  using nlohmann::json;
  json j = study_identity(d, study);
  j["integrator"] = d.integrator;
  j["integrator_order"] = d.integrator_order;
  j["reference_detail"] = d.reference_detail;
  j["member_noun"] = d.particles == 1 ? d.member_nouns.one : d.member_nouns.many;  // as the count reads
  j["time_unit"] = d.time_unit;
  j["units"] = json::object();
  for (const auto& v : study.plan.variables) j["units"][v.name] = v.unit;

  j["levels"] = json::array();
  for (const auto& level : study.levels) {
    json l;
    l["level"] = level.level;
    l["dt"] = level.dt;
    l["steps"] = level.steps;
    l["wall_s"] = level.wall_seconds;
    json by_variable = json::object();
    for (std::size_t v = 0; v < study.orders.size(); ++v) {
      const auto& name = study.plan.variables[v].name;
      const auto& n = level.norms[v];
      const auto& a = study.orders[v];
      l["l2_" + name] = number_or_null(n.l2);
      l["order_" + name] = optional_or_null(a.pairwise[level.level]);
      l["self_difference_" + name] = optional_or_null(study.self_convergence[v].difference[level.level]);
      l["self_order_" + name] = optional_or_null(study.self_convergence[v].order[level.level]);
      l["norms_" + name] = {{"l2", number_or_null(n.l2)},
                            {"rms", number_or_null(n.rms)},
                            {"relative", number_or_null(n.relative)},
                            {"max", number_or_null(n.max)},
                            {"solution_l2", number_or_null(n.reference_l2)},
                            {"round_off_floor", number_or_null(a.floor[level.level])}};
      by_variable[name] = {{"status", to_string(a.status[level.level])}, {"rule", a.rule[level.level]}};
    }
    l["status"] = level_status(study, level.level);
    l["status_by_variable"] = by_variable;
    if (!level.solver_statistics.empty()) l["solver_statistics"] = level.solver_statistics;
    j["levels"].push_back(l);
  }

  json reference_error = json::object(), reference_margin = json::object();
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const auto& name = study.plan.variables[v].name;
    const bool estimated = study.reference.error[v] > 0.0;
    reference_error[name] = estimated ? json(study.reference.error[v]) : json();
    reference_margin[name] = estimated ? number_or_null(study.reference.margin[v]) : json();
  }
  j["reference_error"] = reference_error;
  j["reference_margin"] = reference_margin;
  j["reference_trusted"] = study.reference.trusted;
  if (!d.reference_statistics.empty()) j["reference_statistics"] = d.reference_statistics;

  j["self_convergence"] = json::object();
  for (std::size_t v = 0; v < study.self_convergence.size(); ++v) {
    const SelfConvergence& sc = study.self_convergence[v];
    j["self_convergence"][study.plan.variables[v].name] = {
        {"order", optional_or_null(sc.order.empty() ? std::nullopt : sc.order.back())},
        {"richardson_error", optional_or_null(sc.richardson_error)},
        {"gci", optional_or_null(sc.gci)},
        {"gci_safety_factor", kGciSafetyFactor}};
  }

  j["fitted_order"] = json::object();
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const auto& a = study.orders[v];
    json f;
    if (a.fit.valid) {
      f["value"] = a.fit.value;
      f["stderr"] = number_or_null(a.fit.stderr_);
      f["ci95"] = std::isfinite(a.fit.ci_low) ? json::array({a.fit.ci_low, a.fit.ci_high}) : json();
    } else {
      f["value"] = nullptr;
      f["stderr"] = nullptr;
      f["ci95"] = nullptr;
    }
    f["levels_used"] = a.fit.levels;
    f["exact_to_round_off"] = a.exact_to_round_off;
    j["fitted_order"][study.plan.variables[v].name] = f;
  }
  j["error_constant"] = constants_json(study);
  if (verdict) {
    j["check"] = {{"passed", verdict->passed()},
                  {"verdict", verdict->passed() ? "pass" : verdict->inconclusive() ? "inconclusive" : "fail"},
                  {"expected_order", verdict->expected_order},
                  {"tolerance", verdict->tolerance},
                  {"findings", verdict->lines()}};
    if (!study.plan.expected_order_by_variable.empty())
      j["check"]["expected_order_by_variable"] = study.plan.expected_order_by_variable;
  }
  if (!d.diagnostics.empty()) j["diagnostics"] = d.diagnostics;
  j["options"] = d.options;
  j["provenance"] = d.provenance;
  return j;
}

std::string format_per_particle(const StudyResult& study, const State& reference, const Eigen::ArrayXd& xi) {
  std::vector<Eigen::ArrayXd> errors;
  std::ostringstream out;
  std::vector<std::string> units{"1", "1"}, implied{"1", "1"};  // the particle's number and ξ = r/R
  for (const auto& v : study.plan.variables) {
    units.push_back(v.unit);
    implied.push_back(implied_unit(v.name));
  }
  out << units_line(units, implied);
  out << "particle,xi";
  for (const auto& v : study.plan.variables) {
    out << ",err_" << v.name;
    errors.push_back(member_errors(study.finest, reference, v));
  }
  out << "\n";
  for (Eigen::Index p = 0; p < xi.size(); ++p) {
    out << p << printf_string(",%.17g", xi[p]);
    for (const auto& e : errors) out << printf_string(",%.17g", e[p]);
    out << "\n";
  }
  return out.str();
}

}  // namespace dlpverify
