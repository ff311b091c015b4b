// Error against work from precision JSON (plot.hpp has the picture this draws).
#include <algorithm>
#include <cmath>
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

struct Run {
  double rhs_evals = 0.0, wall_seconds = 0.0;
  std::vector<double> relative_error;  // per plotted variable
  bool reference_limited = false;
};

// The runs of one method in one result, in the order given: the sweep (tolerance tightening,
// step shrinking), so a run that cost more time than a tighter one shows as a step back.
struct MethodRuns {
  std::string method, case_name, label;
  std::size_t result = 0;
  std::vector<Run> runs;
};

// Variables drawn: position (solid, ●) and velocity (dashed, ○) — the brief of issue 5.
const std::vector<std::string> kVariables = {"position", "velocity"};
const char* const kVariableStyle[] = {"dt 1 pt 7", "dt 2 pt 6"};

}  // namespace

void plot_work_precision(const std::vector<json>& results, const PlotOptions& options) {
  plot::figure_format(options.option, options.output);
  if (results.empty()) throw InputError("plot: no work-precision result to draw");

  std::vector<MethodRuns> groups;
  std::vector<std::string> cases, particles;
  for (std::size_t r = 0; r < results.size(); ++r) {
    const std::string where = "work-precision result " + std::to_string(r + 1);
    const json& runs = member(results[r], "runs", where + " (not a precision result)");
    if (!runs.is_array()) throw InputError(where + ": \"runs\" is not a list");
    const std::string case_name = string_or(results[r], "case", "?");
    cases.push_back(case_name);
    if (results[r].contains("particles") && results[r]["particles"].is_number_integer())
      particles.push_back(grouped_digits(results[r]["particles"].get<long long>()));
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const json& run = runs[k];
      const std::string method = string_or(run, "method", "");
      if (method.empty()) throw InputError(where + " run " + std::to_string(k + 1) + ": no \"method\"");
      auto group = std::find_if(groups.begin(), groups.end(),
                                [&](const MethodRuns& g) { return g.result == r && g.method == method; });
      if (group == groups.end()) {
        groups.push_back({method, case_name, method, r, {}});
        group = groups.end() - 1;
      }
      Run point;
      point.rhs_evals = number_or_nan(run, "rhs_evals");
      point.wall_seconds = number_or_nan(run, "wall_s");
      for (const auto& v : kVariables) point.relative_error.push_back(number_or_nan(run, "rel_l2_" + v));
      point.reference_limited = run.contains("reference_limited") && run["reference_limited"].is_boolean() &&
                                run["reference_limited"].get<bool>();
      group->runs.push_back(point);
    }
  }
  if (groups.empty()) throw InputError("plot: the work-precision results hold no runs");
  // A method met in several results is told apart by its case, then by the result's number.
  for (auto& g : groups) {
    const auto same_method = std::count_if(groups.begin(), groups.end(), [&](const MethodRuns& o) { return o.method == g.method; });
    if (same_method < 2) continue;
    const auto same_case = std::count_if(groups.begin(), groups.end(),
                                         [&](const MethodRuns& o) { return o.method == g.method && o.case_name == g.case_name; });
    g.label = g.method + " · " + g.case_name + (same_case > 1 ? format(" #%zu", g.result + 1) : "");
  }

  std::vector<std::string> methods;
  for (const auto& g : groups) methods.push_back(g.method);
  Figure figure;
  figure.title = options.title.empty() ? join_distinct(cases) + " · work–precision: " + join_distinct(methods) +
                                             (particles.empty() ? "" : " · " + join_distinct(particles) + " particles")
                                       : options.title;

  const bool any_limited = std::any_of(groups.begin(), groups.end(), [](const MethodRuns& g) {
    return std::any_of(g.runs.begin(), g.runs.end(), [](const Run& r) { return r.reference_limited; });
  });
  for (int axis = 0; axis < 2; ++axis) {
    const bool by_evaluations = axis == 0;
    Panel panel;
    panel.title = by_evaluations ? "error against RHS evaluations" : "error against wall time";
    panel.x_label = by_evaluations ? "RHS evaluations" : "wall time of the solve [s]";
    panel.y_label = "relative L2 error ‖e‖₂ / ‖y‖₂";
    panel.key = by_evaluations;  // one legend serves both panels
    // Error falls as work grows: the empty corners are top right and bottom left.
    panel.key_preference = {Corner::top_right, Corner::bottom_left, Corner::bottom_right, Corner::top_left};
    const auto work = [&](const Run& r) { return by_evaluations ? r.rhs_evals : r.wall_seconds; };
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const auto& runs = groups[g].runs;
      for (std::size_t v = 0; v < kVariables.size(); ++v) {
        Element e;
        for (const auto& r : runs) e.rows.push_back({work(r), r.relative_error[v]});
        if (std::none_of(e.rows.begin(), e.rows.end(), [](const auto& row) { return std::isfinite(row[1]); })) continue;
        e.style = std::string("with linespoints lw 1.8 ps 1.15*PS ") + kVariableStyle[v] + " lc rgb \"" + series_colour(g) + "\"";
        if (v == 0) e.title = groups[g].label;
        panel.elements.push_back(std::move(e));
      }
      Element limited;
      for (const auto& r : runs)
        if (r.reference_limited)
          for (double error : r.relative_error) limited.rows.push_back({work(r), error});
      if (!limited.rows.empty()) {
        limited.style = "with points pt 6 ps 2.4*PS lw 1.2 lc rgb \"#000000\"";
        panel.elements.push_back(std::move(limited));
      }
    }
    for (std::size_t v = 0; v < kVariables.size(); ++v) {
      Element key;
      key.key_only = true;
      key.style = std::string("with linespoints lw 1.8 ps 1.15*PS ") + kVariableStyle[v] + " lc rgb \"#555555\"";
      key.title = kVariables[v] + (v == 0 ? " (solid, ●)" : " (dashed, ○)");
      panel.elements.push_back(std::move(key));
    }
    if (any_limited) {
      Element key;
      key.key_only = true;
      key.style = "with points pt 6 ps 2.4*PS lw 1.2 lc rgb \"#000000\"";
      key.title = "limited by the reference's own error";
      panel.elements.push_back(std::move(key));
    }
    figure.panels.push_back(std::move(panel));
  }
  figure.shared_y = true;
  lay_out(figure, 760, 640);
  draw(figure, options.output, options.option);
}

}  // namespace dlpverify
