// The figure of a study by tolerance (dlpverify/tolerance_study.hpp): error against rtol, and the
// work spent for it against rtol beside it.
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

// Relative error of each variable against rtol, with the line error = rtol that proportionality
// with constant 1 would follow.
Panel error_panel(const json& study, const std::vector<std::string>& variables) {
  Panel panel{.title = "error against tolerance", .x_label = "rtol", .y_label = "relative L2 error ‖e‖₂ / ‖y‖₂"};
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
  return panel;
}

// The work each run reported: right-hand-side evaluations and steps (none for a program that counts none).
Panel work_panel(const json& study) {
  Panel panel{.title = "work against tolerance", .x_label = "rtol", .y_label = "count per run"};
  const char* keys[] = {"rhs_evals", "steps", "rejected_steps"};
  const char* names[] = {"RHS evaluations", "steps", "rejected steps"};
  for (std::size_t k = 0; k < 3; ++k) {
    Element e{.style = "with linespoints pt 5 lw 1.5 lc rgb \"" + series_colour(k + 3) + "\"", .title = names[k]};
    for (const json& run : study.at("runs")) {
      const double count = number_or_nan(run, keys[k]);
      if (std::isfinite(count) && count > 0.0) e.rows.push_back({number_or_nan(run, "rtol"), count});
    }
    if (!e.rows.empty()) panel.elements.push_back(std::move(e));
  }
  return panel;
}

}  // namespace

std::string plot_tolerance(const json& study, const PlotOptions& options) {
  figure_format(options.option, options.output);
  if (!study.is_object() || !study.contains("runs") || !study.contains("variables"))
    throw InputError(options.option, options.output, "needs the JSON of a study by --tolerances");
  const std::vector<std::string> variables = study.at("variables").get<std::vector<std::string>>();
  Figure figure{options.title, {error_panel(study, variables), work_panel(study)}};
  if (figure.title.empty())
    figure.title = member_or(study, "case", std::string()) + " · " + member_or(study, "integrator", std::string()) +
                   " by tolerance";
  return draw(figure, options.output, options.option);
}

}  // namespace dlpverify
