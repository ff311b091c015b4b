// Figures of the finest level from CSV: each particle's error against ξ, and the L2 error
// against time (plot.hpp has the pictures these draw).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "io/csv_table.hpp"
#include "io/errors.hpp"
#include "plot/figure.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/plot.hpp"

namespace dlpverify {

namespace {

using namespace plot;

// Past this many particles a file is thinned for drawing (a few MB of script, a second of cairo).
constexpr std::size_t kMaxDrawnParticles = 40000;
constexpr int kXiBins = 200;

struct Input {
  CsvTable table;
  std::string label;
};

std::vector<Input> read_inputs(const std::vector<std::string>& paths, const PlotOptions& options,
                               const std::vector<std::string>& required, const std::vector<std::string>& optional) {
  if (paths.empty()) throw InputError("plot: no CSV file to draw");
  if (!options.labels.empty() && options.labels.size() != paths.size())
    throw InputError("plot: " + std::to_string(options.labels.size()) + " labels for " + std::to_string(paths.size()) + " files");
  std::vector<Input> inputs;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    inputs.push_back({read_csv_table(paths[i], required, optional),
                      options.labels.empty() ? std::filesystem::path(paths[i]).stem().string() : options.labels[i]});
    if (inputs.back().table.rows() == 0) throw InputError(paths[i] + ": no rows under the header");
  }
  return inputs;
}

// Variables present in any input, as columns prefix + name, in canonical order.
std::vector<std::string> variables_of(const std::vector<Input>& inputs, const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& in : inputs)
    for (const auto& c : in.table.columns)
      if (c.rfind(prefix, 0) == 0) names.push_back(c.substr(prefix.size()));
  return canonical_variable_order(names);
}

std::string joined_labels(const std::vector<Input>& inputs) {
  std::vector<std::string> labels;
  for (const auto& in : inputs) labels.push_back(in.label);
  return join_distinct(labels);
}

// One input: one panel, a colour per variable. Several: a panel per variable, a colour per input.
// add(panel, input's index, variable, colour, legend) draws one variable of one input.
using AddSeries = std::function<void(Panel&, std::size_t, const std::string&, const std::string&, const std::string&)>;
Figure panels_of(const std::vector<Input>& inputs, const std::vector<std::string>& variables, const std::string& x_label,
                 const std::string& y_name, const AddSeries& add) {
  Figure figure;
  if (inputs.size() == 1) {
    Panel panel{.x_label = x_label, .y_label = y_name + " [" + unit_list(variables) + "]", .x_scale = Scale::linear};
    for (std::size_t v = 0; v < variables.size(); ++v) add(panel, 0, variables[v], series_colour(v), with_unit(variables[v]));
    figure.panels.push_back(std::move(panel));
    return figure;
  }
  for (const auto& variable : variables) {
    Panel panel{.title = variable, .x_label = x_label, .y_label = y_name + " [" + variable_unit(variable) + "]", .x_scale = Scale::linear};
    for (std::size_t i = 0; i < inputs.size(); ++i) add(panel, i, variable, series_colour(i), inputs[i].label);
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

// The rows drawn of a per-particle table: all of them, or every k-th plus the smallest and
// largest error of each ξ bin in any variable, so thinning never hides the worst particle.
std::vector<std::size_t> drawn_rows(const CsvTable& table, const std::vector<std::string>& variables, std::size_t stride) {
  const std::size_t n = table.rows();
  std::vector<char> keep(n, 0);
  for (std::size_t i = 0; i < n; i += stride) keep[i] = 1;
  const auto& xi = table.column("xi");
  double lo = INFINITY, hi = -INFINITY;
  for (double x : xi)
    if (std::isfinite(x)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  const double width = hi > lo ? (hi - lo) / kXiBins : 1.0;
  for (const auto& v : variables) {
    if (stride == 1 || !table.has("err_" + v)) continue;
    const auto& error = table.column("err_" + v);
    std::vector<long> smallest(kXiBins, -1), largest(kXiBins, -1);
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(xi[i]) || !(error[i] > 0.0) || !std::isfinite(error[i])) continue;
      const auto bin = static_cast<std::size_t>(std::clamp(static_cast<int>((xi[i] - lo) / width), 0, kXiBins - 1));
      if (smallest[bin] < 0 || error[i] < error[static_cast<std::size_t>(smallest[bin])]) smallest[bin] = static_cast<long>(i);
      if (largest[bin] < 0 || error[i] > error[static_cast<std::size_t>(largest[bin])]) largest[bin] = static_cast<long>(i);
    }
    for (int b = 0; b < kXiBins; ++b)
      for (long i : {smallest[b], largest[b]})
        if (i >= 0) keep[static_cast<std::size_t>(i)] = 1;
  }
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) rows.push_back(i);
  return rows;
}

// What the figure leaves out or moves: thinned files and errors of exactly 0 (bottom edge).
std::string xi_note(const std::vector<Input>& inputs, const std::vector<std::vector<std::size_t>>& rows, std::size_t zeros) {
  std::string note;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::size_t n = inputs[i].table.rows(), stride = (n + kMaxDrawnParticles - 1) / kMaxDrawnParticles;
    if (stride <= 1) continue;
    note += (note.empty() ? "" : "; ") + (inputs.size() > 1 ? inputs[i].label + ": " : "") +
            grouped_digits(static_cast<long long>(rows[i].size())) + " of " + grouped_digits(static_cast<long long>(n)) +
            format(" particles drawn (every %zu%s, and each ξ bin's extremes)", stride,
                   stride == 2 ? "nd" : stride == 3 ? "rd" : "th");
  }
  if (zeros > 0)
    note += (note.empty() ? "" : "; ") + format("%zu error%s of exactly 0 on the bottom edge", zeros, zeros == 1 ? "" : "s");
  return note;
}

}  // namespace

void plot_error_vs_xi(const std::vector<std::string>& paths, const PlotOptions& options) {
  figure_format(options.option, options.output);
  const auto inputs = read_inputs(paths, options, {"particle", "xi", "err_position", "err_velocity"}, {"err_temperature", "err_mass"});
  const auto variables = variables_of(inputs, "err_");
  std::vector<std::vector<std::size_t>> rows;
  for (const auto& in : inputs)
    rows.push_back(drawn_rows(in.table, variables, (in.table.rows() + kMaxDrawnParticles - 1) / kMaxDrawnParticles));

  // Positive errors where they are, zeros on the bottom edge; smaller points where they crowd.
  const auto scatter = [&](Panel& panel, std::size_t input, const std::string& variable, const std::string& colour,
                           const std::string& legend) {
    const CsvTable& table = inputs[input].table;
    if (!table.has("err_" + variable)) return;
    const auto& xi = table.column("xi");
    const auto& error = table.column("err_" + variable);
    const auto& drawn = rows[input];
    const double size = drawn.size() > 5000 ? 0.45 : drawn.size() > 500 ? 0.7 : 1.0;
    Element points{.style = "with points pt 7 ps " + number(size) + " lc rgb \"" + colour + "\"", .title = legend};
    Element zeros{.style = "with points pt 10 ps 1.0 lc rgb \"" + colour + "\"", .pin = Pin::bottom};
    for (std::size_t i : drawn) (error[i] == 0.0 ? zeros : points).rows.push_back({xi[i], error[i]});
    panel.elements.push_back(std::move(points));
    if (!zeros.rows.empty()) panel.elements.push_back(std::move(zeros));
  };
  Figure figure = panels_of(inputs, variables, "ξ (similarity coordinate of the particle)", "error of the particle ‖yₚ − yₚ(t)‖", scatter);
  figure.title = !options.title.empty() ? options.title
                                        : "where the error lives: each particle's error at the finest level · " + joined_labels(inputs);
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    std::size_t zeros = 0;  // of every particle, drawn or not, that the panel shows
    for (const auto& in : inputs)
      for (const auto& v : variables)
        if ((inputs.size() == 1 || v == variables[p]) && in.table.has("err_" + v))
          zeros += static_cast<std::size_t>(std::count(in.table.column("err_" + v).begin(), in.table.column("err_" + v).end(), 0.0));
    figure.panels[p].key = "top right";  // errors grow outwards, towards ξ = 1, often
    figure.panels[p].note = xi_note(inputs, rows, zeros);
  }
  draw(figure, options.output, options.option);
}

void plot_error_history(const std::vector<std::string>& paths, const PlotOptions& options) {
  figure_format(options.option, options.output);
  // --history also records the reference's own size √Σ‖y‖² (ref_l2_*), for relative errors.
  const auto inputs = read_inputs(paths, options, {"t", "l2_position", "l2_velocity"},
                                  {"l2_temperature", "l2_mass", "ref_l2_position", "ref_l2_velocity", "ref_l2_temperature", "ref_l2_mass"});
  // A line, with points when they are few enough to tell apart.
  const auto series = [&](Panel& panel, std::size_t input, const std::string& variable, const std::string& colour,
                          const std::string& legend) {
    const CsvTable& table = inputs[input].table;
    if (!table.has("l2_" + variable)) return;
    Element e{.title = legend};
    const auto& t = table.column("t");
    const auto& error = table.column("l2_" + variable);
    for (std::size_t i = 0; i < table.rows(); ++i)
      if (error[i] > 0.0) e.rows.push_back({t[i], error[i]});
    e.style = std::string(e.rows.size() <= 40 ? "with linespoints pt 7 ps 0.9" : "with lines") + " lw 2 lc rgb \"" + colour + "\"";
    panel.elements.push_back(std::move(e));
  };
  Figure figure = panels_of(inputs, variables_of(inputs, "l2_"), "t [s]", "L2 error", series);
  figure.title = !options.title.empty() ? options.title : "L2 error against time at the finest level · " + joined_labels(inputs);
  draw(figure, options.output, options.option);
}

}  // namespace dlpverify
