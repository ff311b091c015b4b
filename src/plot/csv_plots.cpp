// Figures of the finest level from CSV: each particle's error against ξ, and the L2 error
// against time (plot.hpp has the pictures these draw).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "io/csv_table.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/result_units.hpp"
#include "plot/figure.hpp"
#include "plot/figures.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/plot.hpp"
#include "io/input_file.hpp"

namespace dlpverify {

namespace {

using namespace plot;

// Past this many particles a file is thinned for drawing (a few MB of script, a second of cairo).
constexpr std::size_t kMaxDrawnParticles = 40000, kXiBins = 200;
std::size_t stride_of(std::size_t particles) { return (particles + kMaxDrawnParticles - 1) / kMaxDrawnParticles; }

struct Inputs {
  std::span<const CsvTable> tables{};  // the caller's (a per-particle table can be hundreds of MB)
  std::vector<std::string> labels{};
  // Columns <prefix><name> in the files' order (each name once), and each one's unit: the units
  // line's, else the one its name implies (io/result_units.hpp).
  std::vector<std::string> variables{}, units{};
  std::vector<std::string> time_units{};  // of each file's column t
  std::string unit(const std::string& variable) const {
    return units[static_cast<std::size_t>(std::find(variables.begin(), variables.end(), variable) - variables.begin())];
  }
};

// The columns after the particle's number and ξ, and after the history's t: a prefix and the
// variable's name. --history writes l2_<variable> and the reference's own size √Σ‖y‖²
// (ref_l2_<variable>), for relative errors.
const std::vector<std::string> kXiRequired = {"particle", "xi"}, kXiPrefixes = {"err_"};
const std::vector<std::string> kHistoryRequired = {"t"}, kHistoryPrefixes = {"l2_", "ref_l2_"};

// The unit of a column: its field of the units line, else `implied`.
std::string unit_of(const CsvTable& table, const std::string& column, const std::string& implied) {
  if (table.units.empty()) return implied;
  return table.units[static_cast<std::size_t>(std::find(table.columns.begin(), table.columns.end(), column) -
                                              table.columns.begin())];
}

Inputs inputs_of(const std::vector<CsvTable>& tables, const PlotOptions& options, const std::string& prefix) {
  if (tables.empty()) throw InputError("plot: no CSV file to draw");
  if (!options.labels.empty() && options.labels.size() != tables.size())
    throw InputError("plot: " + std::to_string(options.labels.size()) + " labels for " +
                     std::to_string(tables.size()) + " files");
  Inputs in{.tables = tables, .labels = options.labels};
  for (const auto& table : tables) {
    if (table.rows() == 0) throw InputError(table.path + ": no rows under the header");
    if (options.labels.empty()) in.labels.push_back(std::filesystem::path(table.path).stem().string());
    if (table.has("t")) in.time_units.push_back(unit_of(table, "t", kImpliedTimeUnit));
    for (const auto& c : table.columns) {
      if (c.rfind(prefix, 0) != 0) continue;
      const std::string name = c.substr(prefix.size());
      if (std::find(in.variables.begin(), in.variables.end(), name) != in.variables.end()) continue;
      in.variables.push_back(name);
      in.units.push_back(unit_of(table, c, implied_unit(name)));
    }
  }
  return in;
}

std::vector<CsvTable> read_tables(const std::vector<std::string>& paths,
                                  CsvTable (*read)(std::istream&, const std::string&)) {
  std::vector<CsvTable> tables;
  for (const auto& path : paths) {
    std::ifstream in;
    try {
      in = open_input_stream("input", path, input_limit::result);
    } catch (const InputError& e) {
      throw InputError(path + ": " + e.reason());
    }
    tables.push_back(read(in, path));
  }
  return tables;
}

// One input as one panel, a colour per variable, or several as a panel per variable, a colour
// per input. add(panel, input's index, variable, colour, legend) draws one variable of one input.
Figure panels(const Inputs& in, const PlotOptions& options, const std::string& title, const std::string& x_label,
              const std::string& y_name, const auto& add) {
  Figure figure{options.title.empty() ? title + " · " + join_distinct(in.labels) : options.title};
  for (std::size_t p = 0; p < (in.tables.size() == 1 ? 1 : in.variables.size()); ++p) {
    const auto& shown = in.tables.size() == 1 ? in.variables : std::vector<std::string>{in.variables[p]};
    std::vector<std::string> units;
    for (const auto& v : shown) units.push_back(in.unit(v));
    Panel panel{.title = in.tables.size() == 1 ? "" : shown[0],
                .x_label = x_label,
                .y_label = with_units(y_name, units),
                .x_scale = Scale::linear};
    for (std::size_t i = 0; i < in.tables.size(); ++i)
      for (std::size_t v = 0; v < shown.size(); ++v)
        add(panel, i, shown[v], series_colour(i + v),
            in.tables.size() == 1 ? with_unit(shown[v], units[v]) : in.labels[i]);
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

// The rows drawn of a per-particle table: every k-th, plus the smallest and largest error in each
// ξ bin of each variable, so that thinning hides neither the worst particle nor a dip. (ξ = r / R
// lies in [0, 1]; anything outside falls in an edge bin.)
std::vector<std::size_t> drawn_rows(const CsvTable& table, const std::vector<std::string>& variables) {
  const std::size_t n = table.rows(), stride = stride_of(n);
  std::vector<char> keep(n + 1, 0);  // keep[n]: where empty bins point
  for (std::size_t i = 0; i < n; i += stride) keep[i] = 1;
  const auto& xi = table.column("xi");
  for (const auto& v : variables) {
    if (stride == 1 || !table.has("err_" + v)) continue;
    const auto& error = table.column("err_" + v);
    std::vector<std::size_t> smallest(kXiBins, n), largest(kXiBins, n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(xi[i]) || !(error[i] > 0.0) || !std::isfinite(error[i])) continue;
      const auto bin = static_cast<std::size_t>(std::clamp(xi[i], 0.0, 1.0) * (kXiBins - 1));
      if (smallest[bin] == n || error[i] < error[smallest[bin]]) smallest[bin] = i;
      if (largest[bin] == n || error[i] > error[largest[bin]]) largest[bin] = i;
    }
    for (std::size_t b = 0; b < kXiBins; ++b) keep[smallest[b]] = keep[largest[b]] = 1;
  }
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) rows.push_back(i);
  return rows;
}

// What the figure leaves out or moves: thinned files and errors of exactly 0 (bottom edge).
std::string xi_note(const Inputs& in, const std::vector<std::vector<std::size_t>>& rows, std::size_t zeros) {
  std::string note;
  for (std::size_t i = 0; i < in.tables.size(); ++i) {
    const std::size_t n = in.tables[i].rows(), stride = stride_of(n);
    const char* ordinal = stride == 2 ? "nd" : stride == 3 ? "rd" : "th";
    if (stride > 1)
      note += (note.empty() ? "" : "; ") + (in.tables.size() > 1 ? in.labels[i] + ": " : "") +
              grouped_digits(rows[i].size()) + " of " + grouped_digits(n) +
              printf_string(" particles drawn (every %zu%s, and each ξ bin's extremes)", stride, ordinal);
  }
  if (zeros > 0)
    note += (note.empty() ? "" : "; ") +
            printf_string("%zu error%s of exactly 0 on the bottom edge", zeros, zeros == 1 ? "" : "s");
  return note;
}

}  // namespace

CsvTable plot::read_per_particle_csv(std::istream& in, const std::string& path) {
  return read_prefixed_csv_table(in, path, kXiRequired, kXiPrefixes);
}

CsvTable plot::read_history_csv(std::istream& in, const std::string& path) {
  return read_prefixed_csv_table(in, path, kHistoryRequired, kHistoryPrefixes);
}

Figure plot::error_vs_xi_figure(const std::vector<CsvTable>& tables, const PlotOptions& options) {
  const Inputs in = inputs_of(tables, options, "err_");
  if (in.variables.empty())
    throw InputError(tables.front().path + ": no err_ column (a per-particle file has particle,xi,err_<variable>,…)");
  std::vector<std::vector<std::size_t>> rows;
  for (const auto& table : in.tables) rows.push_back(drawn_rows(table, in.variables));
  // Positive errors where they are, zeros on the bottom edge; smaller points where they crowd.
  // The note under the axes counts the panel's zeros among every particle, drawn or not.
  std::size_t zeros = 0;
  const auto scatter = [&](Panel& panel, std::size_t i, const std::string& variable, const std::string& colour,
                           const std::string& legend) {
    if (panel.elements.empty()) zeros = 0;  // a new panel
    if (!in.tables[i].has("err_" + variable)) return;
    const auto& xi = in.tables[i].column("xi");
    const auto& error = in.tables[i].column("err_" + variable);
    const double size = rows[i].size() > 5000 ? 0.45 : rows[i].size() > 500 ? 0.7 : 1.0;
    Element points{.style = "with points pt 7 ps " + number(size) + " lc rgb \"" + colour + "\"", .title = legend};
    Element zero{.style = "with points pt 10 ps 1.0 lc rgb \"" + colour + "\"", .pin = Pin::bottom};
    for (std::size_t k : rows[i]) (error[k] == 0.0 ? zero : points).rows.push_back({xi[k], error[k]});
    panel.elements.push_back(std::move(points));
    if (!zero.rows.empty()) panel.elements.push_back(std::move(zero));
    zeros += static_cast<std::size_t>(std::count(error.begin(), error.end(), 0.0));
    panel.note = xi_note(in, rows, zeros);
  };
  return panels(in, options, "where the error lives: each particle's error at the finest level",
                "ξ (similarity coordinate of the particle)", "error of the particle ‖yₚ − yₚ(t)‖", scatter);
}

Figure plot::error_history_figure(const std::vector<CsvTable>& tables, const PlotOptions& options) {
  const Inputs in = inputs_of(tables, options, "l2_");
  if (in.variables.empty())
    throw InputError(tables.front().path + ": no l2_ column (an L2 error history has t,l2_<variable>,…)");
  // A line, with points when they are few enough to tell apart.
  const auto series = [&](Panel& panel, std::size_t i, const std::string& variable, const std::string& colour,
                          const std::string& legend) {
    if (!in.tables[i].has("l2_" + variable)) return;
    Element e{.title = legend};
    const auto& t = in.tables[i].column("t");
    const auto& error = in.tables[i].column("l2_" + variable);
    for (std::size_t k = 0; k < t.size(); ++k)
      if (error[k] > 0.0) e.rows.push_back({t[k], error[k]});
    e.style = std::string(e.rows.size() <= 40 ? "with linespoints pt 7 ps 0.9" : "with lines") + " lw 2 lc rgb \"" +
              colour + "\"";
    panel.elements.push_back(std::move(e));
  };
  return panels(in, options, "L2 error against time at the finest level", with_units("t", in.time_units), "L2 error",
                series);
}

std::string plot_error_vs_xi(const std::vector<std::string>& paths, const PlotOptions& options) {
  figure_format(options.option, options.output);
  const Figure figure = error_vs_xi_figure(read_tables(paths, read_per_particle_csv), options);
  return draw(figure, options.output, options.option);
}

std::string plot_error_history(const std::vector<std::string>& paths, const PlotOptions& options) {
  figure_format(options.option, options.output);
  const Figure figure = error_history_figure(read_tables(paths, read_history_csv), options);
  return draw(figure, options.output, options.option);
}

}  // namespace dlpverify
