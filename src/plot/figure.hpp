// A figure as data — panels of plot elements — and the one function that turns it into a
// GnuplotScript and a file. The figure kinds (convergence, work-precision, error against ξ,
// error history) only build panels; ranges, tics, legend placement and styling live here, so
// the four look alike and none of them writes a gnuplot command with text in it.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "plot/gnuplot_process.hpp"

namespace dlpverify::plot {

enum class Scale { linear, log };

// Where a point sits vertically: at its value; on the top or bottom edge of the axes (an error
// of exactly 0 on a log axis, a NaN); or at its value when that lies within the range the other
// elements set, else on the top edge (an unstable level whose error blew up).
enum class Pin { none, top, bottom, top_when_off_scale };

// One item of a plot command: points, a line, or a legend-only entry (keyentry).
struct Element {
  std::vector<std::vector<double>> rows;  // x y (the y of a point pinned to an edge is ignored)
  std::string style;                      // ours: "with points pt 7 ps 1.3 lc rgb '#0072B2'"
  std::string title;                      // any text; empty: no legend entry
  bool key_only = false;                  // a legend entry without data
  Pin pin = Pin::none;
};

// Text at a data position, left-aligned, in a colour of ours ("#555555").
struct Label {
  std::string text;
  double x = 0.0, y = 0.0;
  std::string colour = "#333333";
};

enum class Corner { top_left, top_right, bottom_left, bottom_right };

struct Panel {
  std::string title;  // above the panel (several panels), or the figure's (one panel)
  std::string x_label, y_label;
  Scale x_scale = Scale::log, y_scale = Scale::log;
  std::vector<Element> elements;
  std::vector<Label> labels;
  std::string note;  // small print under the axes' top edge, e.g. how many particles are drawn
  bool key = true;
  std::vector<Corner> key_preference = {Corner::top_left, Corner::bottom_right, Corner::top_right, Corner::bottom_left};
};

struct Figure {
  std::string title;  // any text
  std::vector<Panel> panels;
  int rows = 1, columns = 1;  // panel layout
  bool shared_y = false;      // one y range for every panel (they show the same quantity)
  Canvas canvas;
};

// Rows × columns for n panels: 1×n up to three, then two rows.
void lay_out(Figure& figure, int panel_width = 760, int panel_height = 620);

// Writes the figure (gnuplot_process.hpp: format from the extension, atomic, InputError /
// SolverError).
void draw(const Figure& figure, const std::string& output, const std::string& option);

// Colour-blind-safe series colours (Okabe & Ito), cycled.
std::string series_colour(std::size_t index);

// Units of the measured variables (docs/model.md §5): "m", "m/s", "K", "kg"; empty when unknown.
std::string variable_unit(const std::string& variable);
// position, velocity, temperature, mass first, any other name after them in the given order.
std::vector<std::string> canonical_variable_order(std::vector<std::string> names);
// The variables' units for an axis label: "m, m/s, K" (unknown units left out).
std::string unit_list(const std::vector<std::string>& variables);

// "a, b, c": the items in order, each once.
std::string join_distinct(const std::vector<std::string>& items);

// 4187856 → "4 187 856" (narrow no-break spaces).
std::string grouped_digits(long long value);

// printf-style formatting into a std::string, for legend text.
std::string format(const char* pattern, auto... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

}  // namespace dlpverify::plot
