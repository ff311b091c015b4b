// The figure of a study by tolerance (dlpverify/tolerance_study.hpp): error against rtol, and the
// work spent for it on a second axis of the same panel.
#include <cmath>
#include <string>
#include <vector>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/json_fields.hpp"
#include "plot/figure.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/plot.hpp"

namespace dlpverify {

namespace {

using nlohmann::json;
using namespace plot;

// One panel, under the figure's title: the relative error of each variable against rtol (left
// axis), with the line error = rtol that proportionality with constant 1 would follow; and on
// the right axis the right-hand-side evaluations each run spent for it (none for a program that
// counts none).
Panel tolerance_panel(const json& study, const std::vector<std::string>& variables) {
  Panel panel{.x_label = "rtol",
              .y_label = "relative L2 error ‖e‖₂ / ‖y‖₂",
              .y2_label = "RHS evaluations per run"};
  Element diagonal{.style = "with lines dt 2 lw 1.5 lc rgb \"#555555\"", .title = "error = rtol"};
  for (std::size_t v = 0; v < variables.size(); ++v) {
    Element e{.style = "with linespoints pt 7 lw 1.5 lc rgb \"" + series_colour(v) + "\"", .title = variables[v]};
    const json& fit = member_or(member_or(study, "proportionality", json()), variables[v], json());
    const double exponent = number_or_nan(fit, "exponent");
    if (std::isfinite(exponent)) e.title += printf_string(": E = %.2f", exponent);
    for (const json& run : study.at("runs")) e.rows.push_back({number_or_nan(run, "rtol"), number_or_nan(run, "relative_" + variables[v])});
    panel.elements.push_back(std::move(e));
  }
  for (const json& run : study.at("runs")) diagonal.rows.push_back({number_or_nan(run, "rtol"), number_or_nan(run, "rtol")});
  panel.elements.push_back(std::move(diagonal));
  // Of an implicit table also the evaluations its Newton iterations spent on J·v.
  const char* keys[] = {"rhs_evals", "rhs_evals_jacobian"};
  const char* names[] = {"RHS evaluations (right axis)", "RHS evaluations for J·v (right axis)"};
  for (std::size_t k = 0; k < 2; ++k) {
    Element work{.style = "with linespoints pt " + std::to_string(5 + 4 * k) + " ps 0.9 dt 3 lw 1.5 lc rgb \"" +
                          series_colour(6 - 3 * k) + "\"",
                 .title = names[k],
                 .y2 = true};
    for (const json& run : study.at("runs")) {
      const double count = number_or_nan(run, keys[k]);
      if (std::isfinite(count) && count > 0.0) work.rows.push_back({number_or_nan(run, "rtol"), count});
    }
    if (!work.rows.empty()) panel.elements.push_back(std::move(work));
  }
  return panel;
}

}  // namespace

std::string plot_tolerance(const json& study, const PlotOptions& options) {
  figure_format(options.option, options.output);
  if (!study.is_object() || !study.contains("runs") || !study.contains("variables"))
    throw InputError(options.option, options.output, "needs the JSON of a study by --tolerances");
  const std::vector<std::string> variables = study.at("variables").get<std::vector<std::string>>();
  Figure figure{options.title, {tolerance_panel(study, variables)}};
  if (figure.title.empty())
    figure.title = member_or(study, "case", std::string()) + " · " + member_or(study, "integrator", std::string()) +
                   " by tolerance";
  return draw(figure, options.output, options.option);
}

}  // namespace dlpverify
