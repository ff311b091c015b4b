// Error against work from precision JSON (plot.hpp has the picture this draws).
#include <algorithm>
#include <cmath>
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

struct Run {
  double rhs_evals = 0.0, wall_seconds = 0.0;
  std::vector<double> relative_error;  // per variable of kVariables
  bool reference_limited = false;
};

// The runs of one method in one result, in the order given: the sweep (tolerance tightening,
// step shrinking), so a run that cost more time than a tighter one shows as a step back.
struct MethodRuns {
  std::string method, case_name;
  std::size_t result = 0;
  std::vector<Run> runs;
};

// Variables drawn: position (solid, ●) and velocity (dashed, ○) — the brief of issue 5.
const std::vector<std::string> kVariables = {"position", "velocity"};
const char* const kVariableStyle[] = {"dt 1 pt 7", "dt 2 pt 6"};
const std::string kLimitedStyle = "with points pt 6 ps 2.4 lw 1.2 lc rgb \"#000000\"";

std::vector<MethodRuns> read_runs(const std::vector<json>& results) {
  std::vector<MethodRuns> groups;
  for (std::size_t r = 0; r < results.size(); ++r) {
    const std::string where = "work-precision result " + std::to_string(r + 1);
    const json& runs = member(results[r], "runs", where + " (not a precision result)");
    if (!runs.is_array()) throw InputError(where + ": \"runs\" is not a list");
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const std::string method = string_or(runs[k], "method", "");
      if (method.empty()) throw InputError(where + " run " + std::to_string(k + 1) + ": no \"method\"");
      auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.result == r && g.method == method; });
      if (group == groups.end()) {
        groups.push_back({method, string_or(results[r], "case", "?"), r, {}});
        group = groups.end() - 1;
      }
      Run run{number_or_nan(runs[k], "rhs_evals"), number_or_nan(runs[k], "wall_s"), {}, flag(runs[k], "reference_limited")};
      for (const auto& v : kVariables) run.relative_error.push_back(number_or_nan(runs[k], "rel_l2_" + v));
      group->runs.push_back(run);
    }
  }
  if (groups.empty()) throw InputError("plot: the work-precision results hold no runs");
  return groups;
}

// One panel: error against RHS evaluations (with the legend) or against wall time.
Panel work_panel(const std::vector<MethodRuns>& groups, const std::vector<std::string>& labels, bool by_evaluations) {
  // Error falls as work grows: the top right is empty. One legend serves both panels.
  Panel panel{.title = by_evaluations ? "error against RHS evaluations" : "error against wall time",
              .x_label = by_evaluations ? "RHS evaluations" : "wall time of the solve [s]",
              .y_label = "relative L2 error ‖e‖₂ / ‖y‖₂",
              .key = by_evaluations ? "top right" : ""};
  const auto work = [&](const Run& r) { return by_evaluations ? r.rhs_evals : r.wall_seconds; };
  bool any_limited = false;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (std::size_t v = 0; v < kVariables.size(); ++v) {
      Element e{.style = std::string("with linespoints lw 1.8 ps 1.15 ") + kVariableStyle[v] + " lc rgb \"" + series_colour(g) + "\"",
                .title = v == 0 ? labels[g] : ""};
      for (const auto& r : groups[g].runs) e.rows.push_back({work(r), r.relative_error[v]});
      if (std::any_of(e.rows.begin(), e.rows.end(), [](const auto& row) { return std::isfinite(row[1]); }))
        panel.elements.push_back(std::move(e));
    }
    // Runs whose error is limited by the reference's own: ringed.
    Element limited{.style = kLimitedStyle};
    for (const auto& r : groups[g].runs)
      if (r.reference_limited)
        for (double error : r.relative_error) limited.rows.push_back({work(r), error});
    any_limited = any_limited || !limited.rows.empty();
    if (!limited.rows.empty()) panel.elements.push_back(std::move(limited));
  }
  for (std::size_t v = 0; v < kVariables.size(); ++v)
    panel.elements.push_back({.style = std::string("with linespoints lw 1.8 ps 1.15 ") + kVariableStyle[v] + " lc rgb \"#555555\"",
                              .title = kVariables[v] + (v == 0 ? " (solid, ●)" : " (dashed, ○)"),
                              .key_only = true});
  if (any_limited)
    panel.elements.push_back({.style = kLimitedStyle, .title = "limited by the reference's own error", .key_only = true});
  return panel;
}

}  // namespace

void plot_work_precision(const std::vector<json>& results, const PlotOptions& options) {
  figure_format(options.option, options.output);
  if (results.empty()) throw InputError("plot: no work-precision result to draw");
  const std::vector<MethodRuns> groups = read_runs(results);
  // A method met in several results is told apart by its case, then by the result's number.
  std::vector<std::string> methods, cases, labels, particles;
  for (const auto& g : groups) {
    methods.push_back(g.method);
    cases.push_back(g.case_name);
  }
  for (std::size_t g = 0; g < groups.size(); ++g) labels.push_back(distinct_label(methods, cases, g, groups[g].result + 1));
  for (const auto& r : results)
    if (integer_or(r, "particles", -1) >= 0) particles.push_back(grouped_digits(integer_or(r, "particles", 0)));

  Figure figure;
  figure.title = !options.title.empty() ? options.title
                                        : join_distinct(cases) + " · work–precision: " + join_distinct(methods) +
                                              (particles.empty() ? "" : " · " + join_distinct(particles) + " particles");
  figure.panels = {work_panel(groups, labels, true), work_panel(groups, labels, false)};
  figure.shared_y = true;
  draw(figure, options.output, options.option);
}

}  // namespace dlpverify
