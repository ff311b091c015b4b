// Figures from JSON results: error against Δt (converge/check) and error against work
// (precision). plot.hpp has the pictures these draw.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/json_fields.hpp"
#include "io/result_units.hpp"
#include "plot/figure.hpp"
#include "plot/figures.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/plot.hpp"

namespace dlpverify {

namespace {

using nlohmann::json;
using namespace plot;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Legend name i of several series: names[i], with cases[i] when another series has the same name,
// and " #number" when it has the same case too ("rk2 · drag #2").
std::string distinct_label(const std::vector<std::string>& names, const std::vector<std::string>& cases, std::size_t i,
                           std::size_t number) {
  std::size_t same_name = 0, same_case = 0;
  for (std::size_t k = 0; k < names.size(); ++k) {
    same_name += names[k] == names[i];
    same_case += names[k] == names[i] && cases[k] == cases[i];
  }
  return same_name < 2 ? names[i] : names[i] + " · " + cases[i] + (same_case > 1 ? " #" + std::to_string(number) : "");
}

// What a level's point looks like: its status (docs/verification.md's words: ok, pre-asymptotic,
// round-off, reference, unstable), and whether the fit used it; a word no status has is `other`.
enum Mark { fitted, ok_not_fitted, pre_asymptotic, reference_limited, round_off, unstable, other, zero };

struct Level {
  double dt, error;  // error: NaN when the report wrote null
  Mark mark;
};

struct Variable {
  std::string name{}, unit{};
  std::vector<Level> levels{};
  double order = std::nan("");  // the fitted order; NaN: none
  std::string fit{};            // for the legend: "p = 2.04 [2.01, 2.07]"
};

struct Study {
  std::string case_name, integrator;
  long long particles = 0;
  std::string member_noun{};    // the word for that count: "particles"
  double expected_order = 0.0;  // of the slope triangle: the order checked against, else the integrator's; NaN: none
  std::string time_unit{};      // of Δt
  std::vector<Variable> variables{};
  bool differences = false;     // analyze without a reference: norms of y_k − y_{k+1}, not errors
};

// Each name once, in the order of first appearance.
std::vector<std::string> distinct(const std::vector<std::string>& names) {
  std::vector<std::string> once;
  for (const auto& n : names)
    if (std::find(once.begin(), once.end(), n) == once.end()) once.push_back(n);
  return once;
}

// The variables a result declares ("variables": names in the problem's order), else, written
// before it did, those its `key_holder` has a member <prefix><name> of, known names first.
std::vector<std::string> declared_variables(const json& result, const json& key_holder, const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& n : member_or(result, "variables", json::array()))
    if (n.is_string() && !n.get<std::string>().empty()) names.push_back(n.get<std::string>());
  if (!names.empty()) return distinct(names);
  if (key_holder.is_object())
    for (const auto& [key, value] : key_holder.items())
      if (key.rfind(prefix, 0) == 0 && key.size() > prefix.size()) names.push_back(key.substr(prefix.size()));
  return canonical_variable_order(names);
}

// A variable's unit as the result gives it ("units": name → unit), else the one its name implies.
std::string unit_of(const json& result, const std::string& variable) {
  return member_or(member_or(result, "units", json::object()), variable, implied_unit(variable));
}

Variable read_variable(const json& levels, const json& fits, const std::string& name, const std::string& where,
                       bool relative) {
  Variable v{.name = name};
  const json f = member_or(fits, name, json::object()), ci = member_or(f, "ci95", json());
  v.order = number_or_nan(f, "value");
  std::vector<int> used;
  for (const auto& l : member_or(f, "levels_used", json::array()))
    if (l.is_number_integer()) used.push_back(l.get<int>());
  if (member_or(f, "exact_to_round_off", false))
    v.fit = "exact to round-off";
  else if (!std::isfinite(v.order))
    v.fit = "no fitted order";
  else if (ci.is_array() && ci.size() == 2 && ci[0].is_number() && ci[1].is_number())
    v.fit = printf_string("p = %.2f [%.2f, %.2f]", v.order, ci[0].get<double>(), ci[1].get<double>());
  else
    v.fit = printf_string("p = %.2f (%zu levels, no interval)", v.order, used.size());
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const json& l = levels[k];
    const json by_variable = member_or(l, "status_by_variable", json::object()),
               norms = member_or(l, "norms_" + name, json());
    const std::string status =
        member_or(by_variable.contains(name) ? by_variable[name] : l, "status", std::string("ok"));
    const double dt = number_or_nan(l, "dt");
    const double error =
        relative && norms.is_object() ? number_or_nan(norms, "relative") : number_or_nan(l, "l2_" + name);
    const bool in_fit =
        std::isfinite(v.order) && std::count(used.begin(), used.end(), member_or(l, "level", int(k))) > 0;
    if (!(dt > 0.0)) throw InputError(where + " level " + std::to_string(k) + ": no positive \"dt\"");
    // Each status its own mark: the legend says what the table says.
    v.levels.push_back({dt, error,
                        status == "unstable"         ? unstable
                        : error == 0.0               ? zero
                        : status == "pre-asymptotic" ? pre_asymptotic
                        : status == "reference"      ? reference_limited
                        : status == "round-off"      ? round_off
                        : status != "ok"             ? other
                        : in_fit                     ? fitted
                                                     : ok_not_fitted});
  }
  return v;
}

Study read_study(const json& j, std::size_t index, bool relative) {
  const std::string where = "study " + std::to_string(index + 1);
  Study s{member_or(j, "case", std::string("?")), member_or(j, "integrator", std::string("?")),
          member_or(j, "particles", 0LL)};
  s.member_noun = member_or(j, "member_noun", std::string(kImpliedMemberNoun));
  s.expected_order = number_or_nan(member_or(j, "check", json()), "expected_order");
  if (!(s.expected_order > 0.0)) s.expected_order = number_or_nan(j, "integrator_order");
  s.time_unit = member_or(j, "time_unit", kImpliedTimeUnit);
  s.differences = member_or(j, "reference", std::string()) == "next run";
  const json& levels = required_member(j, "levels", where + " (not a converge/check result)");
  if (!levels.is_array() || levels.empty()) throw InputError(where + ": \"levels\" is not a list of levels");
  const std::vector<std::string> names = declared_variables(j, levels.front(), "l2_");
  if (names.empty()) throw InputError(where + ": its levels hold no l2_<variable> error");
  const json& fits = required_member(j, "fitted_order", where);
  for (const auto& name : names) {
    s.variables.push_back(read_variable(levels, fits, name, where, relative));
    s.variables.back().unit = unit_of(j, name);
  }
  return s;
}

struct Look {
  const char *points, *legend;
  Pin pin;
};
constexpr Look kLooks[] = {
    {"pt 7 ps 1.35", "ok: in the fit", Pin::none},
    {"pt 6 ps 1.35 lw 1.5", "ok: not in the fit", Pin::none},
    {"pt 8 ps 1.5 lw 1.5", "pre-asymptotic: not fitted", Pin::none},
    {"pt 12 ps 1.6 lw 1.5", "reference-limited: not fitted", Pin::none},
    {"pt 4 ps 1.35 lw 1.5", "round-off: not fitted", Pin::none},
    {"pt 2 ps 1.7 lw 2.2", "unstable: not fitted (top edge if off scale)", Pin::top_when_off_scale},
    {"pt 3 ps 1.5 lw 1.5", "other status: not fitted", Pin::none},
    {"pt 10 ps 1.5 lw 1.5", "error exactly 0 (bottom edge)", Pin::bottom}};

std::string point_style(Mark mark, const std::string& colour) {
  return std::string("with points ") + kLooks[mark].points + " lc rgb \"" + colour + "\"";
}

// Points (by status), the fitted line and the legend entry of one variable of one study.
void add_series(Panel& panel, const Variable& v, const std::string& colour, const std::string& legend,
                std::set<Mark>& marks) {
  for (Mark mark : {fitted, ok_not_fitted, pre_asymptotic, reference_limited, round_off, unstable, other, zero}) {
    Element e{.style = point_style(mark, colour), .pin = kLooks[mark].pin};
    for (const auto& l : v.levels)
      if (l.mark == mark) e.rows.push_back({l.dt, l.error});
    if (e.rows.empty()) continue;
    panel.elements.push_back(std::move(e));
    marks.insert(mark);
  }
  // The least-squares line ln e = c + p ln Δt over the levels used passes through their centroid:
  // c = mean(ln e) − p mean(ln Δt), the intercept the fit had.
  double sum_log_dt = 0.0, sum_log_error = 0.0, dt_min = kInf, dt_max = 0.0;
  int n = 0;
  for (const auto& l : v.levels)
    if (l.mark == fitted && std::isfinite(l.error)) {
      sum_log_dt += std::log(l.dt);
      sum_log_error += std::log(l.error);
      dt_min = std::min(dt_min, l.dt);
      dt_max = std::max(dt_max, l.dt);
      ++n;
    }
  const std::string lc = " lc rgb \"" + colour + "\"";
  const auto line = [&](double dt) { return std::exp(sum_log_error / n + v.order * (std::log(dt) - sum_log_dt / n)); };
  if (n >= 2)
    panel.elements.push_back(
        {.rows = {{dt_min, line(dt_min)}, {dt_max, line(dt_max)}}, .style = "with lines lw 2.2" + lc});
  const char* key = std::isfinite(v.order) ? "with linespoints lw 2.2 pt 7 ps 1.2" : "with points pt 7 ps 1.2";
  panel.elements.push_back({.style = key + lc, .title = legend});
}

// A slope triangle of the expected order p under the finest fitted level, a quarter of its lowest
// error down: legs along Δt (a factor f) and along the error (f^p), the hypotenuse parallel to
// error ∝ Δt^p. Without a fitted level (say a method exact to round-off) there is nothing to
// compare a slope with.
void add_slope_triangle(Panel& panel, double p, const std::vector<const Variable*>& variables,
                        const std::string& colour) {
  double x0 = kInf, y0 = kInf;
  for (const auto* v : variables)
    for (const auto& l : v->levels)
      if (l.mark == fitted && std::isfinite(l.error)) x0 = std::min(x0, l.dt);
  for (const auto* v : variables)
    for (const auto& l : v->levels)
      if (l.dt == x0 && l.error > 0.0 && std::isfinite(l.error)) y0 = std::min(y0, l.error / 4.0);
  if (!(p > 0.0) || !std::isfinite(y0)) return;
  // Wide enough to read, short enough to stay under the data: 0.4 decades of Δt, 1.2 of error at most.
  const double f = std::pow(10.0, std::min(0.4, 1.2 / p));
  const double x1 = x0 * f, y1 = y0 * std::pow(f, p);
  panel.elements.push_back(
      {.rows = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}}, .style = "with lines lw 1.4 lc rgb \"" + colour + "\""});
  panel.elements.push_back({.rows = {{x1, std::sqrt(y0 * y1)}},
                            .style = "with labels left offset character 0.4,0 tc rgb \"" + colour + "\"",
                            .text = printf_string("slope %g", p)});
}

// The runs of one method in one result, in the order given: the sweep (tolerance tightening,
// step shrinking), so a run that cost more time than a tighter one shows as a step back.
struct MethodRuns {
  std::string method, case_name;
  std::size_t result = 0;
  std::vector<const json*> runs{};
};

// A variable's line and points, by its place among the variables drawn (cycled): position
// solid with ●, velocity dashed with ○, and so on.
struct VariableLook {
  const char *style, *legend;
};
constexpr VariableLook kVariableLooks[] = {{"with linespoints lw 1.8 ps 1.15 dt 1 pt 7", " (solid, ●)"},
                                           {"with linespoints lw 1.8 ps 1.15 dt 2 pt 6", " (dashed, ○)"},
                                           {"with linespoints lw 1.8 ps 1.15 dt 3 pt 5", " (dotted, ■)"},
                                           {"with linespoints lw 1.8 ps 1.15 dt 4 pt 4", " (dash-dot, □)"},
                                           {"with linespoints lw 1.8 ps 1.15 dt 5 pt 9", " (dash-dot-dot, ▲)"}};
const VariableLook& variable_look(std::size_t v) { return kVariableLooks[v % std::size(kVariableLooks)]; }
const std::string kLimitedStyle = "with points pt 6 ps 2.4 lw 1.2 lc rgb \"#000000\"";

std::vector<MethodRuns> read_runs(const std::vector<json>& results) {
  std::vector<MethodRuns> groups;
  for (std::size_t r = 0; r < results.size(); ++r) {
    const std::string where = "work-precision result " + std::to_string(r + 1);
    const json& runs = required_member(results[r], "runs", where + " (not a precision result)");
    if (!runs.is_array()) throw InputError(where + ": \"runs\" is not a list");
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const std::string method = member_or(runs[k], "method", std::string());
      if (method.empty()) throw InputError(where + " run " + std::to_string(k + 1) + ": no \"method\"");
      auto g = std::find_if(groups.begin(), groups.end(),
                            [&](const auto& o) { return o.result == r && o.method == method; });
      if (g == groups.end()) {
        groups.push_back({method, member_or(results[r], "case", std::string("?")), r});
        g = groups.end() - 1;
      }
      g->runs.push_back(&runs[k]);
    }
  }
  if (groups.empty()) throw InputError("plot: the work-precision results hold no runs");
  return groups;
}

// Error against RHS evaluations (with the legend) or against wall time.
Panel work_panel(const std::vector<MethodRuns>& groups, const std::vector<std::string>& labels,
                 const std::vector<std::string>& variables, bool by_evaluations) {
  Panel panel{.title = by_evaluations ? "error against RHS evaluations" : "error against wall time",
              .x_label = by_evaluations ? "RHS evaluations" : "wall time of the solve [s]",
              .y_label = "relative L2 error ‖e‖₂ / ‖y‖₂",
              .key = by_evaluations};
  Element limited{.style = kLimitedStyle};  // runs limited by the reference's own error: ringed
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t v = 0; v < variables.size(); ++v) {
      Element e{.style = variable_look(v).style + (" lc rgb \"" + series_colour(g) + "\""), .title = v ? "" : labels[g]};
      for (const json* run : groups[g].runs) {
        e.rows.push_back({number_or_nan(*run, by_evaluations ? "rhs_evals" : "wall_s"),
                          number_or_nan(*run, "rel_l2_" + variables[v])});
        if (member_or(*run, "reference_limited", false)) limited.rows.push_back(e.rows.back());
      }
      if (std::any_of(e.rows.begin(), e.rows.end(), [](const auto& row) { return std::isfinite(row[1]); }))
        panel.elements.push_back(std::move(e));
    }
  for (std::size_t v = 0; v < variables.size(); ++v)
    panel.elements.push_back({.style = variable_look(v).style + std::string(" lc rgb \"#555555\""),
                              .title = variables[v] + variable_look(v).legend});
  if (!limited.rows.empty()) {
    panel.elements.push_back(limited);
    panel.elements.push_back({.style = kLimitedStyle, .title = "limited by the reference's own error"});
  }
  return panel;
}

// The y axis: errors, or the differences between successive runs when every study measured those
// (analyze without a reference), or both.
std::string error_label(const std::vector<Study>& studies, bool relative, const std::vector<std::string>& units) {
  const auto differences = std::count_if(studies.begin(), studies.end(), [](const Study& s) { return s.differences; });
  const std::string norm = differences == 0 ? "L2 error"
                           : differences == static_cast<long>(studies.size()) ? "L2 difference of successive runs"
                                                                               : "L2 error or difference of successive runs";
  return relative ? "relative " + norm + " ‖e‖₂ / ‖y‖₂" : with_units(norm, units);
}

}  // namespace

Figure plot::convergence_figure(const std::vector<json>& studies_json, const PlotOptions& options) {
  if (studies_json.empty()) throw InputError("plot: no convergence study to draw");
  std::vector<Study> studies;
  std::vector<std::string> integrators, cases, counts, names;
  for (std::size_t i = 0; i < studies_json.size(); ++i) {
    studies.push_back(read_study(studies_json[i], i, options.relative_error));
    integrators.push_back(studies[i].integrator);
    cases.push_back(studies[i].case_name);
    counts.push_back(grouped_digits(studies[i].particles) + " " + studies[i].member_noun);
    for (const auto& v : studies[i].variables) names.push_back(v.name);
  }
  Figure figure{options.title};
  if (figure.title.empty())
    figure.title = join_distinct(cases) + " · " + join_distinct(integrators) + " · " + join_distinct(counts) +
                   (options.relative_error ? " · relative errors" : "");
  // One study: one panel, a colour per variable, a grey triangle. Several: a panel per variable,
  // its unit and the unit of time (a step in seconds and a dimensionless one share no axis, nor
  // metres and feet), a colour and a triangle per study.
  const bool one = studies.size() == 1;
  struct Shown {
    std::vector<std::string> variables;
    std::string unit, time_unit;  // several studies: the variable's and its study's
  };
  std::vector<Shown> panels;
  if (one) panels = {{distinct(names), "", studies[0].time_unit}};
  for (const auto& name : one ? std::vector<std::string>{} : distinct(names))
    for (const auto& s : studies)
      for (const auto& v : s.variables) {
        const Shown key{{name}, v.unit, s.time_unit};
        const bool listed = std::any_of(panels.begin(), panels.end(), [&key](const Shown& p) {
          return p.variables == key.variables && p.unit == key.unit && p.time_unit == key.time_unit;
        });
        if (v.name == name && !listed) panels.push_back(key);
      }
  for (const Shown& shown : panels) {
    const auto drawn_here = [&](const Study& s, const Variable& v) {
      return s.time_unit == shown.time_unit && (one || v.unit == shown.unit) &&
             std::find(shown.variables.begin(), shown.variables.end(), v.name) != shown.variables.end();
    };
    std::vector<std::string> units;
    for (const auto& s : studies)
      for (const auto& v : s.variables)
        if (drawn_here(s, v)) units.push_back(v.unit);
    const std::string step = with_units("Δt", {shown.time_unit});
    const bool split = std::count_if(panels.begin(), panels.end(), [&](const Shown& p) {
                         return p.variables == shown.variables;
                       }) > 1;
    Panel panel{.title = one ? "" : split ? with_unit(shown.variables[0], shown.unit) + " · " + step : shown.variables[0],
                .x_label = step,
                .y_label = error_label(studies, options.relative_error, units)};
    std::set<Mark> marks;
    for (std::size_t i = 0; i < studies.size(); ++i) {
      std::vector<const Variable*> drawn;
      for (const auto& v : studies[i].variables) {
        if (!drawn_here(studies[i], v)) continue;
        const std::string name = !one                     ? distinct_label(integrators, cases, i, i + 1)
                                 : options.relative_error ? v.name
                                                          : with_unit(v.name, v.unit);
        add_series(panel, v, series_colour(one ? drawn.size() : i), name + ": " + v.fit, marks);
        drawn.push_back(&v);
      }
      add_slope_triangle(panel, studies[i].expected_order, drawn, one ? "#555555" : series_colour(i));
    }
    // The statuses' legend, unless every point is ok and fitted.
    for (Mark mark : marks == std::set<Mark>{fitted} ? std::set<Mark>{} : marks)
      panel.elements.push_back({.style = point_style(mark, "#555555"), .title = kLooks[mark].legend});
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

Figure plot::work_precision_figure(const std::vector<json>& results, const PlotOptions& options) {
  if (results.empty()) throw InputError("plot: no work-precision result to draw");
  const std::vector<MethodRuns> groups = read_runs(results);
  std::vector<std::string> methods, cases, labels, particles;
  for (const auto& g : groups) {
    methods.push_back(g.method);
    cases.push_back(g.case_name);
  }
  // A method in several results is told apart by its case, then by the result's number.
  for (std::size_t g = 0; g < groups.size(); ++g)
    labels.push_back(distinct_label(methods, cases, g, groups[g].result + 1));
  for (const auto& r : results)
    if (member_or(r, "particles", -1LL) >= 0)
      particles.push_back(grouped_digits(member_or(r, "particles", 0LL)) + " " +
                          member_or(r, "member_noun", std::string(kImpliedMemberNoun)));
  std::vector<std::string> variables;
  for (const auto& g : groups) {
    const auto declared = declared_variables(results[g.result], *g.runs.front(), "rel_l2_");
    variables.insert(variables.end(), declared.begin(), declared.end());
  }
  variables = distinct(variables);
  Figure figure{options.title,
                {work_panel(groups, labels, variables, true), work_panel(groups, labels, variables, false)}};
  if (figure.title.empty())
    figure.title = join_distinct(cases) + " · work–precision: " + join_distinct(methods) +
                   (particles.empty() ? "" : " · " + join_distinct(particles));
  return figure;
}

std::string plot_convergence(const std::vector<json>& studies, const PlotOptions& options) {
  figure_format(options.option, options.output);
  return draw(convergence_figure(studies, options), options.output, options.option);
}

std::string plot_work_precision(const std::vector<json>& results, const PlotOptions& options) {
  figure_format(options.option, options.output);
  return draw(work_precision_figure(results, options), options.output, options.option);
}

}  // namespace dlpverify
