// Figures of the finest level from CSV: each particle's error against ξ, and the L2 error
// against time (plot.hpp has the pictures these draw).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/csv_table.hpp"
#include "plot/figure.hpp"
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
    throw InputError("plot: " + std::to_string(options.labels.size()) + " labels for " + std::to_string(paths.size()) +
                     " files");
  std::vector<Input> inputs;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    Input in{read_csv_table(paths[i], required, optional), ""};
    in.label = options.labels.empty() ? std::filesystem::path(paths[i]).stem().string() : options.labels[i];
    if (in.table.rows() == 0) throw InputError(paths[i] + ": no rows under the header");
    inputs.push_back(std::move(in));
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

std::string with_unit(const std::string& variable) {
  const std::string unit = variable_unit(variable);
  return unit.empty() ? variable : variable + " [" + unit + "]";
}

std::string joined_labels(const std::vector<Input>& inputs) {
  std::string text;
  for (const auto& in : inputs) text += (text.empty() ? "" : ", ") + in.label;
  return text;
}

// The rows drawn of a per-particle table: all of them, or every k-th plus the smallest and
// largest error of each ξ bin in any variable, so thinning never hides the worst particle.
std::vector<std::size_t> drawn_rows(const CsvTable& table, const std::vector<std::string>& variables, std::size_t& stride) {
  const std::size_t n = table.rows();
  std::vector<std::size_t> rows;
  stride = 1;
  if (n <= kMaxDrawnParticles) {
    rows.resize(n);
    for (std::size_t i = 0; i < n; ++i) rows[i] = i;
    return rows;
  }
  stride = (n + kMaxDrawnParticles - 1) / kMaxDrawnParticles;
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
    if (!table.has("err_" + v)) continue;
    const auto& error = table.column("err_" + v);
    std::vector<long> smallest(kXiBins, -1), largest(kXiBins, -1);
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(xi[i]) || !(error[i] > 0.0) || !std::isfinite(error[i])) continue;
      const int bin = std::clamp(static_cast<int>((xi[i] - lo) / width), 0, kXiBins - 1);
      if (smallest[bin] < 0 || error[i] < error[static_cast<std::size_t>(smallest[bin])]) smallest[bin] = static_cast<long>(i);
      if (largest[bin] < 0 || error[i] > error[static_cast<std::size_t>(largest[bin])]) largest[bin] = static_cast<long>(i);
    }
    for (int b = 0; b < kXiBins; ++b) {
      if (smallest[b] >= 0) keep[static_cast<std::size_t>(smallest[b])] = 1;
      if (largest[b] >= 0) keep[static_cast<std::size_t>(largest[b])] = 1;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) rows.push_back(i);
  return rows;
}

// Points of one variable of one table: positive errors where they are, zeros on the bottom edge.
void add_scatter(Panel& panel, const CsvTable& table, const std::vector<std::size_t>& rows, const std::string& variable,
                 const std::string& colour, const std::string& title, std::size_t& zeros) {
  if (!table.has("err_" + variable)) return;
  const auto& xi = table.column("xi");
  const auto& error = table.column("err_" + variable);
  Element points, zero;
  for (std::size_t i : rows) {
    if (error[i] > 0.0)
      points.rows.push_back({xi[i], error[i]});
    else if (error[i] == 0.0)
      zero.rows.push_back({xi[i], 0.0});
  }
  for (std::size_t i = 0; i < table.rows(); ++i) zeros += error[i] == 0.0;
  const double size = rows.size() > 5000 ? 0.45 : rows.size() > 500 ? 0.7 : 1.0;
  points.style = "with points pt 7 ps " + number(size) + "*PS lc rgb \"" + colour + "\"";
  points.title = title;
  panel.elements.push_back(std::move(points));
  if (!zero.rows.empty()) {
    zero.style = "with points pt 10 ps 1.0*PS lc rgb \"" + colour + "\"";
    zero.pin = Pin::bottom;
    panel.elements.push_back(std::move(zero));
  }
}

std::string thinning_note(const std::vector<Input>& inputs, const std::vector<std::size_t>& drawn,
                          const std::vector<std::size_t>& strides, std::size_t zeros) {
  std::string note;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (strides[i] <= 1) continue;
    note += (note.empty() ? "" : "; ") + (inputs.size() > 1 ? inputs[i].label + ": " : std::string()) +
            grouped_digits(static_cast<long long>(drawn[i])) + " of " +
            grouped_digits(static_cast<long long>(inputs[i].table.rows())) + format(" particles drawn (every %zu", strides[i]) +
            (strides[i] == 2 ? "nd" : strides[i] == 3 ? "rd" : "th") + ", and each ξ bin's extremes)";
  }
  if (zeros > 0)
    note += (note.empty() ? "" : "; ") + format("%zu error%s of exactly 0 on the bottom edge", zeros, zeros == 1 ? "" : "s");
  return note;
}

}  // namespace

void check_plot_path(const std::string& option, const std::string& path) {
  plot::figure_format(option, path);
  check_output_path(option, path);
}

void plot_error_vs_xi(const std::vector<std::string>& paths, const PlotOptions& options) {
  plot::figure_format(options.option, options.output);
  const auto inputs = read_inputs(paths, options, {"particle", "xi", "err_position", "err_velocity"},
                                  {"err_temperature", "err_mass"});
  const auto variables = variables_of(inputs, "err_");
  std::vector<std::vector<std::size_t>> rows;
  std::vector<std::size_t> strides, drawn;
  for (const auto& in : inputs) {
    std::size_t stride = 1;
    rows.push_back(drawn_rows(in.table, variables, stride));
    strides.push_back(stride);
    drawn.push_back(rows.back().size());
  }

  Figure figure;
  figure.title = options.title.empty() ? "where the error lives: each particle's error at the finest level · " + joined_labels(inputs)
                                       : options.title;
  std::size_t zeros = 0;
  if (inputs.size() == 1) {
    Panel panel;
    panel.x_scale = Scale::linear;
    panel.x_label = "ξ (similarity coordinate of the particle)";
    panel.y_label = "error of the particle ‖yₚ − yₚ(t)‖ [" + unit_list(variables) + "]";
    for (std::size_t v = 0; v < variables.size(); ++v)
      add_scatter(panel, inputs[0].table, rows[0], variables[v], series_colour(v), with_unit(variables[v]), zeros);
    panel.note = thinning_note(inputs, drawn, strides, zeros);
    figure.panels.push_back(std::move(panel));
    figure.canvas = Canvas{1100, 760, 13.0};
  } else {
    for (const auto& variable : variables) {
      Panel panel;
      panel.title = variable;
      panel.x_scale = Scale::linear;
      panel.x_label = "ξ";
      panel.y_label = "error of the particle [" + variable_unit(variable) + "]";
      std::size_t panel_zeros = 0;
      for (std::size_t i = 0; i < inputs.size(); ++i)
        add_scatter(panel, inputs[i].table, rows[i], variable, series_colour(i), inputs[i].label, panel_zeros);
      panel.note = thinning_note(inputs, drawn, strides, panel_zeros);
      figure.panels.push_back(std::move(panel));
    }
    lay_out(figure);
  }
  draw(figure, options.output, options.option);
}

void plot_error_history(const std::vector<std::string>& paths, const PlotOptions& options) {
  plot::figure_format(options.option, options.output);
  // --history also records the reference's own size √Σ‖y‖² (ref_l2_*), for relative errors.
  const auto inputs = read_inputs(paths, options, {"t", "l2_position", "l2_velocity"},
                                  {"l2_temperature", "l2_mass", "ref_l2_position", "ref_l2_velocity",
                                   "ref_l2_temperature", "ref_l2_mass"});
  const auto variables = variables_of(inputs, "l2_");

  const auto series = [](const CsvTable& table, const std::string& variable, const std::string& colour,
                         const std::string& title) {
    Element e;
    const auto& t = table.column("t");
    const auto& error = table.column("l2_" + variable);
    for (std::size_t i = 0; i < table.rows(); ++i)
      if (error[i] > 0.0) e.rows.push_back({t[i], error[i]});
    e.style = std::string(e.rows.size() <= 40 ? "with linespoints pt 7 ps 0.9*PS" : "with lines") + " lw 2 lc rgb \"" +
              colour + "\"";
    e.title = title;
    return e;
  };

  Figure figure;
  figure.title = options.title.empty() ? "L2 error against time at the finest level · " + joined_labels(inputs) : options.title;
  if (inputs.size() == 1) {
    Panel panel;
    panel.x_scale = Scale::linear;
    panel.x_label = "t [s]";
    panel.y_label = "L2 error [" + unit_list(variables) + "]";
    for (std::size_t v = 0; v < variables.size(); ++v)
      if (inputs[0].table.has("l2_" + variables[v]))
        panel.elements.push_back(series(inputs[0].table, variables[v], series_colour(v), with_unit(variables[v])));
    figure.panels.push_back(std::move(panel));
    figure.canvas = Canvas{1100, 760, 13.0};
  } else {
    for (const auto& variable : variables) {
      Panel panel;
      panel.title = variable;
      panel.x_scale = Scale::linear;
      panel.x_label = "t [s]";
      panel.y_label = "L2 error [" + variable_unit(variable) + "]";
      for (std::size_t i = 0; i < inputs.size(); ++i)
        if (inputs[i].table.has("l2_" + variable))
          panel.elements.push_back(series(inputs[i].table, variable, series_colour(i), inputs[i].label));
      figure.panels.push_back(std::move(panel));
    }
    lay_out(figure);
  }
  draw(figure, options.output, options.option);
}

}  // namespace dlpverify
