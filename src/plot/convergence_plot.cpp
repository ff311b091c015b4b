// Error against Δt from converge/check JSON (plot.hpp has the picture this draws).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "io/errors.hpp"
#include "plot/figure.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/json_access.hpp"
#include "plot/plot.hpp"

namespace dlpverify {

namespace {

using nlohmann::json;
using namespace plot;

constexpr double kInf = std::numeric_limits<double>::infinity();

struct LevelPoint {
  int level = 0;
  double dt = 0.0, error = 0.0;  // error: NaN when the report wrote null
  std::string status;            // ok | round-off | unstable
};

struct VariableData {
  std::string name{};
  std::vector<LevelPoint> points{};
  double order = std::nan("");  // the fitted order; NaN: none
  std::optional<std::pair<double, double>> ci95{};
  std::vector<int> levels_used{};
  bool exact_to_round_off = false;

  bool fit_valid() const { return std::isfinite(order); }
  bool fitted(int level) const { return std::count(levels_used.begin(), levels_used.end(), level) > 0; }
};

struct StudyData {
  std::string case_name, integrator;
  long long particles = 0;
  double expected_order = 0.0;  // 0: none known
  std::vector<VariableData> variables{};
};

VariableData read_variable(const json& levels, const json& fits, const std::string& name, const std::string& where,
                           bool relative) {
  VariableData v{.name = name};
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const json& level = levels[k];
    LevelPoint p{static_cast<int>(integer_or(level, "level", static_cast<long long>(k))), number_or_nan(level, "dt"), 0.0, "ok"};
    if (!(p.dt > 0.0)) throw InputError(where + " level " + std::to_string(k) + ": no positive \"dt\"");
    p.error = relative && level.contains("norms_" + name) ? number_or_nan(level["norms_" + name], "relative")
                                                           : number_or_nan(level, "l2_" + name);
    // A status per variable when the report has one, else the level's.
    if (level.contains("status_by_variable") && level["status_by_variable"].contains(name))
      p.status = string_or(level["status_by_variable"][name], "status", "ok");
    else
      p.status = string_or(level, "status", "ok");
    v.points.push_back(p);
  }
  if (!fits.contains(name) || !fits[name].is_object()) return v;
  const json& f = fits[name];
  v.order = number_or_nan(f, "value");
  if (f.contains("ci95") && f["ci95"].is_array() && f["ci95"].size() == 2 && f["ci95"][0].is_number() && f["ci95"][1].is_number())
    v.ci95 = std::make_pair(f["ci95"][0].get<double>(), f["ci95"][1].get<double>());
  if (f.contains("levels_used") && f["levels_used"].is_array())
    for (const auto& l : f["levels_used"])
      if (l.is_number_integer()) v.levels_used.push_back(l.get<int>());
  v.exact_to_round_off = flag(f, "exact_to_round_off");
  return v;
}

StudyData read_study(const json& j, std::size_t index, bool relative) {
  const std::string where = "study " + std::to_string(index + 1);
  StudyData s{.case_name = string_or(j, "case", "?"), .integrator = string_or(j, "integrator", "?"),
              .particles = integer_or(j, "particles", 0)};
  // The order checked against, else the integrator's: the slope triangle's.
  s.expected_order = j.contains("check") ? number_or_nan(j["check"], "expected_order") : std::nan("");
  if (!(s.expected_order > 0.0)) s.expected_order = number_or_nan(j, "integrator_order");
  if (!(s.expected_order > 0.0)) s.expected_order = 0.0;

  const json& levels = member(j, "levels", where + " (not a converge/check result)");
  if (!levels.is_array() || levels.empty()) throw InputError(where + ": \"levels\" is not a list of levels");
  std::vector<std::string> names;
  for (const auto& [key, value] : levels.front().items())
    if (key.rfind("l2_", 0) == 0) names.push_back(key.substr(3));
  if (names.empty()) throw InputError(where + ": its levels hold no l2_<variable> error");
  const json& fits = member(j, "fitted_order", where);
  for (const auto& name : canonical_variable_order(names))
    s.variables.push_back(read_variable(levels, fits, name, where, relative));
  return s;
}

std::string fit_text(const VariableData& v) {
  if (v.exact_to_round_off) return "exact to round-off";
  if (!v.fit_valid()) return "no fitted order";
  if (v.ci95) return format("p = %.2f [%.2f, %.2f]", v.order, v.ci95->first, v.ci95->second);
  return format("p = %.2f (%zu levels, no interval)", v.order, v.levels_used.size());
}

// What a level's point looks like: its status, and whether the fit used it.
enum Mark { fitted, ok_not_fitted, round_off, unstable, zero };
struct MarkLook {
  const char* points;
  const char* legend;
  Pin pin;
};
constexpr MarkLook kLooks[] = {{"pt 7 ps 1.35", "ok: in the fit", Pin::none},
                               {"pt 6 ps 1.35 lw 1.5", "ok: not in the fit", Pin::none},
                               {"pt 4 ps 1.35 lw 1.5", "round-off: not fitted", Pin::none},
                               {"pt 2 ps 1.7 lw 2.2", "unstable: not fitted (top edge if off scale)", Pin::top_when_off_scale},
                               {"pt 10 ps 1.5 lw 1.5", "error exactly 0 (bottom edge)", Pin::bottom}};

Mark mark_of(const VariableData& v, const LevelPoint& p) {
  if (p.status == "unstable") return unstable;
  if (p.error == 0.0) return zero;
  if (p.status != "ok") return round_off;  // round-off, or any other word: not part of the fit
  return v.fit_valid() && v.fitted(p.level) ? fitted : ok_not_fitted;
}

std::string point_style(Mark mark, const std::string& colour) {
  return std::string("with points ") + kLooks[mark].points + " lc rgb \"" + colour + "\"";
}

// Points (by status), the fitted line and the legend entry of one variable of one study.
void add_series(Panel& panel, const VariableData& v, const std::string& colour, const std::string& legend,
                std::set<Mark>& marks_used) {
  for (Mark mark : {fitted, ok_not_fitted, round_off, unstable, zero}) {
    Element e{.style = point_style(mark, colour), .pin = kLooks[mark].pin};
    for (const auto& p : v.points)
      if (mark_of(v, p) == mark) e.rows.push_back({p.dt, p.error});
    if (e.rows.empty()) continue;
    marks_used.insert(mark);
    panel.elements.push_back(std::move(e));
  }
  // The least-squares line ln e = c + p ln Δt over the levels used passes through their centroid:
  // c = mean(ln e) − p mean(ln Δt), the intercept the fit had.
  double sum_log_dt = 0.0, sum_log_error = 0.0, dt_min = kInf, dt_max = 0.0;
  int n = 0;
  for (const auto& p : v.points)
    if (v.fitted(p.level) && p.error > 0.0 && std::isfinite(p.error)) {
      sum_log_dt += std::log(p.dt);
      sum_log_error += std::log(p.error);
      dt_min = std::min(dt_min, p.dt);
      dt_max = std::max(dt_max, p.dt);
      ++n;
    }
  const std::string lc = " lc rgb \"" + colour + "\"";
  if (v.fit_valid() && n >= 2) {
    const auto line = [&](double dt) { return std::exp(sum_log_error / n + v.order * (std::log(dt) - sum_log_dt / n)); };
    panel.elements.push_back({.rows = {{dt_min, line(dt_min)}, {dt_max, line(dt_max)}}, .style = "with lines lw 2.2" + lc});
  }
  panel.elements.push_back({.style = (v.fit_valid() ? "with linespoints lw 2.2 pt 7 ps 1.2" : "with points pt 7 ps 1.2") + lc,
                            .title = legend,
                            .key_only = true});
}

// A slope triangle of the expected order p under the finest level the first fitted variable used:
// legs along Δt (a factor f) and along the error (f^p), the hypotenuse parallel to error ∝ Δt^p.
// Without a fitted order (a method exact to round-off) a slope has nothing to be compared with.
void add_slope_triangle(Panel& panel, const StudyData& study, const std::vector<const VariableData*>& variables,
                        const std::string& colour) {
  const double p = study.expected_order;
  const auto first_fitted = std::find_if(variables.begin(), variables.end(),
                                         [](const VariableData* v) { return v->fit_valid() && !v->levels_used.empty(); });
  if (!(p > 0.0) || first_fitted == variables.end()) return;
  const int anchor = *std::max_element((*first_fitted)->levels_used.begin(), (*first_fitted)->levels_used.end());
  double x0 = 0.0, lowest = kInf, dt_min = kInf, dt_max = 0.0;
  for (const auto* v : variables)
    for (const auto& pt : v->points) {
      dt_min = std::min(dt_min, pt.dt);
      dt_max = std::max(dt_max, pt.dt);
      if (pt.level != anchor) continue;
      x0 = pt.dt;
      if (pt.error > 0.0 && std::isfinite(pt.error)) lowest = std::min(lowest, pt.error);
    }
  if (!(x0 > 0.0) || !std::isfinite(lowest)) return;
  // Wide enough to read, short enough to stay under the data: at most 0.6 decades of Δt or of error.
  const double f = std::pow(10.0, std::min({0.6, 1.2 / p, std::max(0.2, 0.35 * std::log10(dt_max / dt_min))}));
  const double y0 = lowest / 4.0, x1 = x0 * f, y1 = y0 * std::pow(f, p);
  panel.elements.push_back({.rows = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}}, .style = "with lines lw 1.4 lc rgb \"" + colour + "\""});
  panel.labels.push_back({format("slope %g", p), x1, std::sqrt(y0 * y1), colour});
}

// The statuses' legend, unless every point is ok and fitted.
void add_mark_legend(Panel& panel, const std::set<Mark>& marks_used) {
  if (marks_used == std::set<Mark>{fitted}) return;
  for (Mark mark : marks_used)
    panel.elements.push_back({.style = point_style(mark, "#555555"), .title = kLooks[mark].legend, .key_only = true});
}

}  // namespace

void plot_convergence(const std::vector<json>& studies_json, const PlotOptions& options) {
  figure_format(options.option, options.output);
  if (studies_json.empty()) throw InputError("plot: no convergence study to draw");
  std::vector<StudyData> studies;
  std::vector<std::string> integrators, cases, counts, labels;
  for (std::size_t i = 0; i < studies_json.size(); ++i) {
    studies.push_back(read_study(studies_json[i], i, options.relative_error));
    integrators.push_back(studies[i].integrator);
    cases.push_back(studies[i].case_name);
    counts.push_back(grouped_digits(studies[i].particles));
  }
  for (std::size_t i = 0; i < studies.size(); ++i) labels.push_back(distinct_label(integrators, cases, i, i + 1));

  Figure figure;
  figure.title = !options.title.empty() ? options.title
                                        : join_distinct(cases) + " · " + join_distinct(integrators) + " · " +
                                              join_distinct(counts) + " particles" + (options.relative_error ? " · relative errors" : "");
  const std::string relative_label = "relative L2 error ‖e‖₂ / ‖y‖₂";
  // One study: one panel, a colour per variable. Several: a panel per variable, a colour per study.
  if (studies.size() == 1) {
    const StudyData& study = studies.front();
    Panel panel{.x_label = "Δt [s]", .y_label = relative_label};
    std::vector<std::string> names;
    std::vector<const VariableData*> variables;
    std::set<Mark> marks_used;
    for (std::size_t v = 0; v < study.variables.size(); ++v) {
      const auto& var = study.variables[v];
      names.push_back(var.name);
      variables.push_back(&var);
      add_series(panel, var, series_colour(v), (options.relative_error ? var.name : with_unit(var.name)) + ": " + fit_text(var),
                 marks_used);
    }
    if (!options.relative_error) panel.y_label = "L2 error [" + unit_list(names) + "]";
    add_slope_triangle(panel, study, variables, "#555555");
    add_mark_legend(panel, marks_used);
    figure.panels.push_back(std::move(panel));
  } else {
    std::vector<std::string> all_names;
    for (const auto& s : studies)
      for (const auto& v : s.variables) all_names.push_back(v.name);
    for (const auto& name : canonical_variable_order(all_names)) {
      const std::string unit = variable_unit(name);
      Panel panel{.title = name,
                  .x_label = "Δt [s]",
                  .y_label = options.relative_error ? relative_label : unit.empty() ? "L2 error" : "L2 error [" + unit + "]"};
      std::set<Mark> marks_used;
      for (std::size_t i = 0; i < studies.size(); ++i)
        for (const auto& v : studies[i].variables)
          if (v.name == name) {
            add_series(panel, v, series_colour(i), labels[i] + ": " + fit_text(v), marks_used);
            add_slope_triangle(panel, studies[i], {&v}, series_colour(i));
          }
      add_mark_legend(panel, marks_used);
      figure.panels.push_back(std::move(panel));
    }
  }
  draw(figure, options.output, options.option);
}

}  // namespace dlpverify
