// A figure as data (panels of plot elements) and the one function that draws it. The figure
// kinds only build panels; ranges, tics, the legend and styling live here, so the four kinds
// look alike and none of them writes a gnuplot command with text in it.
#pragma once

#include <string>
#include <vector>

#include "plot/gnuplot_script.hpp"

namespace dlpverify::plot {

enum class Scale { linear, log };  // of x: y (an error) is always log

// Where a point sits vertically: at its value; on the bottom edge (an error of exactly 0); or at
// its value when the axis holds it, else on the top edge (an unstable level's error, or NaN).
enum class Pin { none, bottom, top_when_off_scale };

struct Element {
  std::vector<std::vector<double>> rows{};  // x y; none: a legend entry only
  std::string style{};                      // ours: "with points pt 7 lc rgb \"#0072B2\""
  std::string title{};                      // any text; empty: no legend entry
  Pin pin = Pin::none;
  std::string text{};  // any text, drawn at each row by a style "with labels …", with room on its right
  bool y2 = false;     // against the panel's second (right, log) axis
};

struct Panel {
  std::string title{};  // above the panel (several panels), or the figure's (one panel)
  std::string x_label{}, y_label{};
  std::string y2_label{};  // the right axis, drawn when an element is on it
  Scale x_scale = Scale::log;
  std::vector<Element> elements{};
  std::string note{};  // small print under the axes, e.g. how many particles are drawn
  bool key = true;     // top left; y grows upwards to leave it room, shown or not (alike panels, alike ranges)
};

struct Figure {
  std::string title{};  // any text
  std::vector<Panel> panels{};
};

// The script that draws the figure, on width × height pixels. One panel: 1100 × 760 pixels;
// several: 760 × 640 each, in one row up to three, else two rows.
struct FigureScript {
  GnuplotScript script;
  int width = 0, height = 0;
};
FigureScript figure_script(const Figure& figure);

// The figure drawn for `output` (render_figure: the format from the extension), to be written by
// the caller's OutputSet.
std::string draw(const Figure& figure, const std::string& output, const std::string& option);

std::string series_colour(std::size_t index);  // colour-blind-safe (Okabe & Ito), cycled

// Results written before units were recorded: their variables with a name of io/result_units.hpp
// first, in its order (position, velocity, temperature, mass, pressure), then any other name.
std::vector<std::string> canonical_variable_order(std::vector<std::string> names);
// "position [m]", "Δt [s]"; the label alone when the unit is dimensionless ("" or "1").
std::string with_unit(const std::string& label, const std::string& unit);
// The distinct units that are not dimensionless, "m, m/s", for an axis that shows several.
std::string unit_list(const std::vector<std::string>& units);
// An axis label with the units of what it shows: "L2 error [m, m/s]", "L2 error" when none has one.
std::string with_units(const std::string& label, const std::vector<std::string>& units);

std::string join_distinct(const std::vector<std::string>& items);  // "a, b, c": each once, in order
std::string grouped_digits(std::size_t value);                     // 4187856 → "4 187 856" (narrow no-break spaces)

}  // namespace dlpverify::plot
