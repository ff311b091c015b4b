// A figure as data — panels of plot elements — and the one function that draws it. The figure
// kinds (convergence, work-precision, error against ξ, error history) only build panels; ranges,
// tics, the legend and styling live here, so the four look alike and none of them writes a
// gnuplot command with text in it.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace dlpverify::plot {

enum class Scale { linear, log };

// Where a point sits vertically: at its value; on the top or bottom edge of the axes (an error of
// exactly 0 on a log axis); or at its value when that lies within the range the other elements
// set, else on the top edge (an unstable level whose error blew up, or NaN).
enum class Pin { none, top, bottom, top_when_off_scale };

// One item of a plot command: points or a line, or a legend entry without data.
struct Element {
  std::vector<std::vector<double>> rows{};  // x y
  std::string style{};                      // ours: "with points pt 7 ps 1.3 lc rgb '#0072B2'"
  std::string title{};                      // any text; empty: no legend entry
  bool key_only = false;
  Pin pin = Pin::none;
};

// Text at a data position, left-aligned, in a colour of ours.
struct Label {
  std::string text;
  double x = 0.0, y = 0.0;
  std::string colour = "#333333";
};

struct Panel {
  std::string title{};  // above the panel (several panels), or the figure's (one panel)
  std::string x_label{}, y_label{};
  Scale x_scale = Scale::log, y_scale = Scale::log;
  std::vector<Element> elements{};
  std::vector<Label> labels{};
  std::string note{};  // small print under the axes, e.g. how many particles are drawn
  // The legend's corner, chosen by each figure kind where its data seldom go ("top left" for
  // errors that grow with Δt); empty: no legend. The y range grows upwards until the data clear it.
  std::string key = "top left";
};

struct Figure {
  std::string title;  // any text
  std::vector<Panel> panels;
  bool shared_y = false;  // one y range for every panel (they show the same quantity)
};

// Writes the figure to `output` (gnuplot_script.hpp: format from the extension, whole or not at
// all, InputError / SolverError). One panel: 1100 × 760 pixels; several: 760 × 640 each, in one
// row up to three, else two rows.
void draw(const Figure& figure, const std::string& output, const std::string& option);

// Colour-blind-safe series colours (Okabe & Ito), cycled.
std::string series_colour(std::size_t index);

// Units of the measured variables (SPEC §5): "m", "m/s", "K", "kg"; empty when unknown.
std::string variable_unit(const std::string& variable);
// "position [m]", or the bare name when the unit is unknown.
std::string with_unit(const std::string& variable);
// position, velocity, temperature, mass first, any other name after them in the given order.
std::vector<std::string> canonical_variable_order(std::vector<std::string> names);
// The variables' units for an axis label: "m, m/s, K" (unknown units left out).
std::string unit_list(const std::vector<std::string>& variables);
// "a, b, c": the items in order, each once.
std::string join_distinct(const std::vector<std::string>& items);
// Legend name i of several series: names[i], with cases[i] when another series has the same name,
// and " #number" when it has the same case too ("rk2 · drag #2").
std::string distinct_label(const std::vector<std::string>& names, const std::vector<std::string>& cases, std::size_t i,
                           std::size_t number);
// 4187856 → "4 187 856" (narrow no-break spaces).
std::string grouped_digits(long long value);

// printf-style formatting into a std::string, for legend text.
std::string format(const char* pattern, auto... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

}  // namespace dlpverify::plot
