// Error against Δt from converge/check JSON (plot.hpp has the picture this draws).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dlpverify/errors.hpp"
#include "plot/figure.hpp"
#include "plot/json_access.hpp"
#include "plot/plot.hpp"

namespace dlpverify {

namespace {

using nlohmann::json;
using namespace plot;

struct LevelPoint {
  int level = 0;
  double dt = 0.0;
  double error = 0.0;  // NaN when the report wrote null
  std::string status;  // ok | round-off | unstable
};

struct VariableData {
  std::string name;
  std::vector<LevelPoint> points;
  bool fit_valid = false;
  double order = 0.0;
  std::optional<std::pair<double, double>> ci95;
  std::vector<int> levels_used;
  bool exact_to_round_off = false;

  bool fitted(int level) const { return std::find(levels_used.begin(), levels_used.end(), level) != levels_used.end(); }
};

struct StudyData {
  std::string case_name, integrator, label;
  long long particles = 0;
  double expected_order = 0.0;  // 0: none known
  std::vector<VariableData> variables;

  const VariableData* variable(const std::string& name) const {
    for (const auto& v : variables)
      if (v.name == name) return &v;
    return nullptr;
  }
};

StudyData read_study(const json& j, std::size_t index, bool relative) {
  const std::string where = "study " + std::to_string(index + 1);
  StudyData s;
  s.case_name = string_or(j, "case", "?");
  s.integrator = string_or(j, "integrator", "?");
  if (j.is_object() && j.contains("particles") && j["particles"].is_number_integer()) s.particles = j["particles"].get<long long>();
  if (j.is_object() && j.contains("check") && j["check"].is_object())
    s.expected_order = number_or_nan(j["check"], "expected_order");
  if (!(s.expected_order > 0.0)) s.expected_order = number_or_nan(j, "integrator_order");
  if (!(s.expected_order > 0.0)) s.expected_order = 0.0;

  const json& levels = member(j, "levels", where + " (not a converge/check result)");
  if (!levels.is_array() || levels.empty()) throw InputError(where + ": \"levels\" is not a list of levels");
  std::vector<std::string> names;
  for (const auto& [key, value] : levels.front().items())
    if (key.rfind("l2_", 0) == 0) names.push_back(key.substr(3));
  if (names.empty()) throw InputError(where + ": its levels hold no l2_<variable> error");
  const json& fits = member(j, "fitted_order", where);

  for (const auto& name : canonical_variable_order(names)) {
    VariableData v;
    v.name = name;
    for (std::size_t k = 0; k < levels.size(); ++k) {
      const json& level = levels[k];
      LevelPoint p;
      p.level = level.is_object() && level.contains("level") && level["level"].is_number_integer() ? level["level"].get<int>()
                                                                                                   : static_cast<int>(k);
      p.dt = number_or_nan(level, "dt");
      if (!(p.dt > 0.0)) throw InputError(where + " level " + std::to_string(k) + ": no positive \"dt\"");
      p.error = relative && level.contains("norms_" + name) ? number_or_nan(level["norms_" + name], "relative")
                                                             : number_or_nan(level, "l2_" + name);
      p.status = "ok";
      if (level.contains("status_by_variable") && level["status_by_variable"].contains(name))
        p.status = string_or(level["status_by_variable"][name], "status", "ok");
      else if (level.contains("status"))
        p.status = string_or(level, "status", "ok");
      v.points.push_back(p);
    }
    if (fits.contains(name) && fits[name].is_object()) {
      const json& f = fits[name];
      v.order = number_or_nan(f, "value");
      v.fit_valid = std::isfinite(v.order);
      if (f.contains("ci95") && f["ci95"].is_array() && f["ci95"].size() == 2 && f["ci95"][0].is_number() &&
          f["ci95"][1].is_number())
        v.ci95 = std::make_pair(f["ci95"][0].get<double>(), f["ci95"][1].get<double>());
      if (f.contains("levels_used") && f["levels_used"].is_array())
        for (const auto& l : f["levels_used"])
          if (l.is_number_integer()) v.levels_used.push_back(l.get<int>());
      v.exact_to_round_off = f.contains("exact_to_round_off") && f["exact_to_round_off"].is_boolean() &&
                             f["exact_to_round_off"].get<bool>();
    }
    s.variables.push_back(std::move(v));
  }
  return s;
}

std::string fit_text(const VariableData& v) {
  if (v.exact_to_round_off) return "exact to round-off";
  if (!v.fit_valid) return "no fitted order";
  if (v.ci95) return format("p = %.2f [%.2f, %.2f]", v.order, v.ci95->first, v.ci95->second);
  return format("p = %.2f (%zu levels, no interval)", v.order, v.levels_used.size());
}

// What a level's point looks like: its status, and whether the fit used it.
enum class Mark { fitted, ok_not_fitted, round_off, unstable, zero };

Mark mark_of(const VariableData& v, const LevelPoint& p) {
  if (p.status == "unstable") return Mark::unstable;
  if (p.error == 0.0) return Mark::zero;
  if (p.status == "round-off") return Mark::round_off;
  if (p.status == "ok" && (v.fitted(p.level) || !v.fit_valid)) return v.fit_valid ? Mark::fitted : Mark::ok_not_fitted;
  if (p.status == "ok") return Mark::ok_not_fitted;
  return Mark::round_off;  // any other word: not part of the fit either
}

std::string point_style(Mark mark, const std::string& colour) {
  const std::string lc = " lc rgb \"" + colour + "\"";
  switch (mark) {
    case Mark::fitted: return "with points pt 7 ps 1.35*PS" + lc;
    case Mark::ok_not_fitted: return "with points pt 6 ps 1.35*PS lw 1.5" + lc;
    case Mark::round_off: return "with points pt 4 ps 1.35*PS lw 1.5" + lc;
    case Mark::unstable: return "with points pt 2 ps 1.7*PS lw 2.2" + lc;
    case Mark::zero: return "with points pt 10 ps 1.5*PS lw 1.5" + lc;
  }
  return {};
}

std::string mark_legend(Mark mark) {
  switch (mark) {
    case Mark::fitted: return "ok: in the fit";
    case Mark::ok_not_fitted: return "ok: not in the fit";
    case Mark::round_off: return "round-off: not fitted";
    case Mark::unstable: return "unstable: not fitted (top edge if off scale)";
    case Mark::zero: return "error exactly 0 (bottom edge)";
  }
  return {};
}

// Points (by status), the fitted line and the legend entry of one variable of one study.
void add_series(Panel& panel, const VariableData& v, const std::string& colour, const std::string& legend,
                std::set<Mark>& marks_used) {
  for (Mark mark : {Mark::fitted, Mark::ok_not_fitted, Mark::round_off, Mark::unstable, Mark::zero}) {
    Element e;
    for (const auto& p : v.points)
      if (mark_of(v, p) == mark) e.rows.push_back({p.dt, p.error});
    if (e.rows.empty()) continue;
    e.style = point_style(mark, colour);
    e.pin = mark == Mark::unstable ? Pin::top_when_off_scale : mark == Mark::zero ? Pin::bottom : Pin::none;
    marks_used.insert(mark);
    panel.elements.push_back(std::move(e));
  }
  // The least-squares line ln e = c + p ln Δt over the levels used: it passes through their
  // centroid, so c = mean(ln e) − p mean(ln Δt) — the intercept GSL fitted.
  double sum_log_dt = 0.0, sum_log_error = 0.0, dt_min = std::numeric_limits<double>::infinity(), dt_max = 0.0;
  int n = 0;
  for (const auto& p : v.points)
    if (v.fitted(p.level) && p.error > 0.0 && std::isfinite(p.error)) {
      sum_log_dt += std::log(p.dt);
      sum_log_error += std::log(p.error);
      dt_min = std::min(dt_min, p.dt);
      dt_max = std::max(dt_max, p.dt);
      ++n;
    }
  if (v.fit_valid && n >= 2) {
    const double c = sum_log_error / n - v.order * sum_log_dt / n;
    Element line;
    line.rows = {{dt_min, std::exp(c + v.order * std::log(dt_min))}, {dt_max, std::exp(c + v.order * std::log(dt_max))}};
    line.style = "with lines lw 2.2 lc rgb \"" + colour + "\"";
    panel.elements.push_back(std::move(line));
  }
  Element key;
  key.key_only = true;
  key.style = (v.fit_valid ? "with linespoints lw 2.2 pt 7 ps 1.2*PS lc rgb \"" : "with points pt 7 ps 1.2*PS lc rgb \"") + colour + "\"";
  key.title = legend;
  panel.elements.push_back(std::move(key));
}

// A slope triangle of the expected order under the line at the finest fitted level: legs along
// Δt (a factor f) and along the error (f^p), the hypotenuse parallel to an error ∝ Δt^p.
void add_slope_triangle(Panel& panel, const StudyData& study, const std::vector<const VariableData*>& variables,
                        const std::string& colour) {
  if (!(study.expected_order > 0.0) || variables.empty()) return;
  // Without a fitted order (a method exact to round-off) a slope has nothing to be compared with.
  if (std::none_of(variables.begin(), variables.end(), [](const VariableData* v) { return v->fit_valid; })) return;
  const double p = study.expected_order;
  // The anchor: the finest level the first fitted variable used.
  std::optional<int> anchor;
  for (const auto* v : variables) {
    if (!v->fit_valid || v->levels_used.empty()) continue;
    anchor = *std::max_element(v->levels_used.begin(), v->levels_used.end());
    break;
  }
  double dt_min = std::numeric_limits<double>::infinity(), dt_max = 0.0;
  for (const auto& pt : variables.front()->points) {
    dt_min = std::min(dt_min, pt.dt);
    dt_max = std::max(dt_max, pt.dt);
  }
  if (!anchor) return;
  double x0 = 0.0, lowest = std::numeric_limits<double>::infinity();
  for (const auto* v : variables)
    for (const auto& pt : v->points)
      if (pt.level == *anchor) {
        x0 = pt.dt;
        if (pt.error > 0.0 && std::isfinite(pt.error)) lowest = std::min(lowest, pt.error);
      }
  if (!(x0 > 0.0) || !std::isfinite(lowest)) return;
  const double span_decades = std::log10(dt_max / dt_min);
  const double f = std::pow(10.0, std::min({0.6, 1.2 / p, std::max(0.2, 0.35 * span_decades)}));
  const double y0 = lowest / 4.0, x1 = x0 * f, y1 = y0 * std::pow(f, p);
  Element triangle;
  triangle.rows = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}};
  triangle.style = "with lines lw 1.4 dt 1 lc rgb \"" + colour + "\"";
  panel.elements.push_back(std::move(triangle));
  panel.labels.push_back({format("slope %g", p), x1, std::sqrt(y0 * y1), colour});
}

std::string particles_text(const std::vector<StudyData>& studies) {
  std::vector<std::string> counts;
  for (const auto& s : studies) counts.push_back(grouped_digits(s.particles));
  return join_distinct(counts) + " particles";
}

void add_mark_legend(Panel& panel, const std::set<Mark>& marks_used) {
  if (marks_used.size() <= 1 && marks_used.count(Mark::fitted)) return;  // all ok: nothing to explain
  for (Mark mark : marks_used) {
    Element e;
    e.key_only = true;
    e.style = point_style(mark, "#555555");
    e.title = mark_legend(mark);
    panel.elements.push_back(std::move(e));
  }
}

}  // namespace

void plot_convergence(const std::vector<json>& studies_json, const PlotOptions& options) {
  plot::figure_format(options.option, options.output);
  if (studies_json.empty()) throw InputError("plot: no convergence study to draw");
  std::vector<StudyData> studies;
  for (std::size_t i = 0; i < studies_json.size(); ++i) studies.push_back(read_study(studies_json[i], i, options.relative_error));

  // Legend names: the integrator, with the case when two studies share one, then a number.
  std::vector<std::string> names, cases;
  for (const auto& s : studies) {
    names.push_back(s.integrator);
    cases.push_back(s.case_name);
  }
  for (std::size_t i = 0; i < studies.size(); ++i) {
    studies[i].label = studies[i].integrator;
    if (std::count(names.begin(), names.end(), studies[i].integrator) > 1) {
      studies[i].label += " · " + studies[i].case_name;
      std::size_t same = 0;
      for (std::size_t k = 0; k < studies.size(); ++k)
        same += names[k] == names[i] && cases[k] == cases[i];
      if (same > 1) studies[i].label += format(" #%zu", i + 1);
    }
  }

  std::vector<std::string> integrators;
  for (const auto& s : studies) integrators.push_back(s.integrator);
  Figure figure;
  figure.title = options.title.empty()
                     ? join_distinct(cases) + " · " + join_distinct(integrators) + " · " + particles_text(studies) +
                           (options.relative_error ? " · relative errors" : "")
                     : options.title;
  const std::string x_label = "Δt [s]";
  const std::string relative_label = "relative L2 error ‖e‖₂ / ‖y‖₂";

  if (studies.size() == 1) {
    const StudyData& study = studies.front();
    Panel panel;
    panel.x_label = x_label;
    std::vector<std::string> variable_names;
    std::set<Mark> marks_used;
    std::vector<const VariableData*> variables;
    for (std::size_t v = 0; v < study.variables.size(); ++v) {
      const auto& var = study.variables[v];
      const std::string unit = variable_unit(var.name);
      variable_names.push_back(var.name);
      const std::string name = options.relative_error || unit.empty() ? var.name : var.name + " [" + unit + "]";
      add_series(panel, var, series_colour(v), name + ": " + fit_text(var), marks_used);
      variables.push_back(&var);
    }
    panel.y_label = options.relative_error ? relative_label : "L2 error [" + unit_list(variable_names) + "]";
    add_slope_triangle(panel, study, variables, "#555555");
    add_mark_legend(panel, marks_used);
    figure.panels.push_back(std::move(panel));
    figure.canvas = Canvas{1100, 760, 13.0};
  } else {
    std::vector<std::string> all_names;
    for (const auto& s : studies)
      for (const auto& v : s.variables) all_names.push_back(v.name);
    for (const auto& name : canonical_variable_order(all_names)) {
      if (std::count(all_names.begin(), all_names.end(), name) == 0) continue;
      Panel panel;
      const std::string unit = variable_unit(name);
      panel.title = name;
      panel.x_label = x_label;
      panel.y_label = options.relative_error ? relative_label : (unit.empty() ? "L2 error" : "L2 error [" + unit + "]");
      std::set<Mark> marks_used;
      for (std::size_t i = 0; i < studies.size(); ++i) {
        const VariableData* v = studies[i].variable(name);
        if (!v) continue;
        add_series(panel, *v, series_colour(i), studies[i].label + ": " + fit_text(*v), marks_used);
        add_slope_triangle(panel, studies[i], {v}, series_colour(i));
      }
      add_mark_legend(panel, marks_used);
      figure.panels.push_back(std::move(panel));
    }
    lay_out(figure);
  }
  draw(figure, options.output, options.option);
}

}  // namespace dlpverify
