#include "plot/figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/result_units.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/plot.hpp"

namespace dlpverify::plot {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kWidth = 1100, kHeight = 760, kPanelWidth = 760, kPanelHeight = 640;  // pixels
// What a panel's title, tics and axis label leave of its height, and the height of a legend
// line (13-point text at 96 dpi, gnuplot's spacing): a rule of thumb, not a text metric.
constexpr double kFramePx = 150.0, kKeyLinePx = 21.0;

// Axis coordinates: log10 of the value on a log axis, the value on a linear one.
double to_axis(double value, Scale scale) { return scale == Scale::log ? std::log10(value) : value; }
double from_axis(double t, Scale scale) { return scale == Scale::log ? std::pow(10.0, t) : t; }
bool on_axis(double value, Scale scale) { return std::isfinite(value) && (scale == Scale::linear || value > 0.0); }

struct Range {
  double lo = kInf, hi = -kInf;
  void add(double t) {
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  double span() const { return hi - lo; }
};

// The data's extent with a margin, so no point sits on the frame (at least 0.06 decades on a
// log axis, something around a single value); a default when there is no data.
Range padded(Range r, Scale scale, double fraction) {
  if (!(r.lo <= r.hi)) return scale == Scale::log ? Range{-3.0, 0.0} : Range{0.0, 1.0};
  const double single = r.span() > 0.0 ? 0.0 : scale == Scale::log ? 0.5 : std::max(std::abs(r.lo), 1.0) * 0.1;
  const double pad = std::max({fraction * r.span(), scale == Scale::log ? 0.06 : 0.0, single});
  return {r.lo - pad, r.hi + pad};
}

// Ranges from the data (pinned points only widen x), with room right of text for the text. Then
// the legend's rule: y grows upwards until the data keep the lower 1 − f of the axes, f the
// legend's share of the height, so the legend at the top covers nothing.
// The second y axis (elements with y2) follows the same rules as the first.
struct PanelRanges {
  Range x, y, y2;
};
PanelRanges ranges_of(const Panel& p, double plot_height_px) {
  Range x, y, y2, text;
  int key_lines = 0;
  for (const auto& e : p.elements) {
    key_lines += !e.title.empty();
    for (const auto& row : e.rows)
      if (row.size() >= 2 && on_axis(row[0], p.x_scale)) {
        (e.text.empty() ? x : text).add(to_axis(row[0], p.x_scale));
        if (e.pin == Pin::none && on_axis(row[1], Scale::log)) (e.y2 ? y2 : y).add(to_axis(row[1], Scale::log));
      }
  }
  x = padded(x, p.x_scale, 0.05);
  y = padded(y, Scale::log, 0.06);
  y2 = padded(y2, Scale::log, 0.06);
  x.hi = std::max(x.hi, text.hi + 0.16 * x.span());
  const double key_share = std::min(0.6, (key_lines + 1.0) * kKeyLinePx / plot_height_px);
  if (key_lines > 0)
    for (Range* r : {&y, &y2}) r->hi = r->lo + r->span() / (1.0 - key_share);
  return {x, y, y2};
}

bool has_y2(const Panel& p) {
  return std::any_of(p.elements.begin(), p.elements.end(), [](const Element& e) { return e.y2; });
}

// The rows of an element as drawn: pinned points just inside their edge, points off a log axis
// (zero, negative, NaN) left out.
std::vector<std::vector<double>> placed(const Element& e, const Panel& p, const Range& y_range) {
  std::vector<std::vector<double>> rows;
  for (const auto& row : e.rows) {
    if (row.size() < 2 || !on_axis(row[0], p.x_scale)) continue;
    const double t = on_axis(row[1], Scale::log) ? to_axis(row[1], Scale::log) : kInf;
    if (e.pin == Pin::none && t == kInf) continue;
    const bool on_scale = t >= y_range.lo && t <= y_range.hi;
    const double y = e.pin == Pin::bottom                            ? y_range.lo + 0.012 * y_range.span()
                     : e.pin == Pin::top_when_off_scale && !on_scale ? y_range.hi - 0.012 * y_range.span()
                                                                     : t;
    rows.push_back({row[0], from_axis(y, Scale::log)});
  }
  return rows;
}

// Log axes over three decades get gnuplot's decade tics, as 10^k; narrower ones, where gnuplot
// would label one decade or none, tics at 1, 2 and 5 × 10^k with minor tics at the other integer
// mantissas. Counts (RHS evaluations) read better as 50, 100, 200.
void axis(GnuplotScript& s, const std::string& a, Scale scale, const Range& r) {
  const double lo = from_axis(r.lo, scale), hi = from_axis(r.hi, scale);
  const bool counts = lo >= 1.0 && hi <= 1e5;
  s.command(std::string(scale == Scale::log ? "set" : "unset") + " logscale " + a);
  s.command("set " + a + "range [" + number(lo) + ":" + number(hi) + "]");
  s.command("set format " + a + (scale == Scale::log && !counts ? " \"10^{%L}\"" : " \"%g\""));
  s.command("set m" + a + "tics default");
  std::string tics;
  // lo > 0 also keeps log10 finite for the cast to int (a linear axis may start at or below 0).
  const bool narrow = scale == Scale::log && lo > 0.0 && hi / lo < 1e3;
  for (int k = narrow ? static_cast<int>(std::floor(std::log10(lo))) : 1; narrow && k <= std::log10(hi); ++k)
    for (int m = 1; m <= 9; ++m) {
      const double v = m * std::pow(10.0, k);
      const bool major = m == 1 || m == 2 || m == 5;
      if (v < lo || v > hi) continue;
      const std::string label = counts   ? printf_string("%g", v)
                                : m == 1 ? printf_string("10^{%d}", k)
                                         : printf_string("%d×10^{%d}", m, k);
      tics += tics.empty() ? "(" : ", ";
      tics += (major ? s.text(label) + " " : "\"\" ") + number(v) + (major ? "" : " 1");
    }
  s.command("set " + a + "tics " + (tics.empty() ? std::string("autofreq") : tics + ")"));
}

// A panel's commands: data as datablocks, all text as text(); an element without rows to draw
// is a legend entry only (keyentry).
void panel_commands(GnuplotScript& s, const Figure& figure, const Panel& p, double plot_height_px, bool several) {
  const auto [x, y, y2] = ranges_of(p, plot_height_px);
  const bool second_axis = has_y2(p);
  s.command("unset label");
  s.command("set tmargin " + number(several ? 3.4 : 3.2));
  s.command("set bmargin " + number(p.note.empty() ? 3.6 : 4.7));
  s.command("set rmargin " + number(second_axis ? 11.5 : 3));
  axis(s, "x", p.x_scale, x);
  axis(s, "y", Scale::log, y);
  if (second_axis) {
    axis(s, "y2", Scale::log, y2);
    s.command("set ytics nomirror");
    s.command("set y2label " + s.text(p.y2_label) + " noenhanced offset -0.5,0");
  } else {
    s.command("unset y2tics");
    s.command("unset y2label");
    s.command("set ytics mirror");
  }
  s.command("set xlabel " + s.text(p.x_label) + " noenhanced offset 0,0.3");
  s.command("set ylabel " + s.text(p.y_label) + " noenhanced offset 0.5,0");
  const std::string& title = several || !p.title.empty() ? p.title : figure.title;
  s.command(title.empty() ? "unset title"
                          : "set title " + s.text(title) + " noenhanced font \"," + (several ? "14" : "15") + "\"");
  s.command(p.key ? "set key top left opaque box lc rgb \"#bbbbbb\" samplen 2.2 spacing 1.1 reverse Left"
                  : "unset key");
  if (!p.note.empty())
    s.command("set label 1 " + s.text(p.note) +
              " at graph 1, graph 0 right offset 0,-3.4 tc rgb \"#555555\" font \",11\" noenhanced");
  // gnuplot needs one item with data even when there is nothing to show: a NaN point leads.
  std::string plot = "plot " + s.table({{std::nan(""), std::nan("")}}) + " using 1:2 with points notitle";
  for (const auto& e : p.elements) {
    const auto rows = placed(e, p, e.y2 ? y2 : y);
    if (rows.empty() && e.title.empty()) continue;
    const std::string columns = (e.text.empty() ? " using 1:2 " : " using 1:2:(" + s.text(e.text) + ") ") +
                                (e.y2 ? "axes x1y2 " : "");
    plot += ", " + (rows.empty() ? "keyentry " : s.table(rows) + columns) + e.style;
    plot += e.title.empty() ? " notitle" : " title " + s.text(e.title) + " noenhanced";
  }
  s.command(plot);
}

}  // namespace

FigureScript figure_script(const Figure& figure) {
  if (figure.panels.empty()) throw std::logic_error("a figure without panels");
  const int n = static_cast<int>(figure.panels.size()), rows = n <= 3 ? 1 : 2, columns = (n + rows - 1) / rows;
  const bool several = n > 1;
  const int panel_height = several ? kPanelHeight : kHeight;

  FigureScript f{.script = {},
                 .width = (several ? kPanelWidth : kWidth) * columns,
                 .height = panel_height * rows + (several ? 40 : 0)};
  GnuplotScript& s = f.script;
  s.command("set grid xtics ytics mxtics mytics back lt 1 lw 0.8 lc rgb \"#d9d9d9\", lt 1 lw 0.5 lc rgb \"#eeeeee\"");
  s.command("set lmargin 11.5");  // fixed side margins: panels side by side line up (rmargin: per panel)
  if (several)
    s.command("set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) + " title " +
              s.text(figure.title) + " noenhanced font \",15\"");
  for (const auto& panel : figure.panels) panel_commands(s, figure, panel, panel_height - kFramePx, several);
  if (several) s.command("unset multiplot");
  return f;
}

std::string draw(const Figure& figure, const std::string& output, const std::string& option) {
  figure_format(option, output);  // a bad name fails before any work
  const FigureScript f = figure_script(figure);
  return render_figure(f.script, f.width, f.height, output, option);
}

std::string series_colour(std::size_t index) {
  static constexpr std::array colours = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                         "#E69F00", "#56B4E9", "#000000", "#8C564B"};
  return colours[index % colours.size()];
}

std::vector<std::string> canonical_variable_order(std::vector<std::string> names) {
  std::vector<std::string> ordered;
  for (const auto& known : implied_variables())
    if (std::find(names.begin(), names.end(), known) != names.end()) ordered.push_back(known);
  for (const auto& n : names)
    if (std::find(ordered.begin(), ordered.end(), n) == ordered.end()) ordered.push_back(n);
  return ordered;
}

std::string with_unit(const std::string& label, const std::string& unit) {
  return dimensionless(unit) ? label : label + " [" + unit + "]";
}

std::string unit_list(const std::vector<std::string>& units) {
  std::vector<std::string> shown;
  for (const auto& u : units)
    if (!dimensionless(u)) shown.push_back(u);
  return join_distinct(shown);
}

std::string with_units(const std::string& label, const std::vector<std::string>& units) {
  const std::string list = unit_list(units);
  return list.empty() ? label : label + " [" + list + "]";
}

std::string join_distinct(const std::vector<std::string>& items) {
  std::string text;
  for (auto it = items.begin(); it != items.end(); ++it)
    if (std::find(items.begin(), it, *it) == it) text += (text.empty() ? "" : ", ") + *it;
  return text;
}

std::string grouped_digits(std::size_t value) {
  const std::string digits = std::to_string(value);
  std::string text;
  for (std::size_t i = 0; i < digits.size(); ++i)
    text += (i > 0 && (digits.size() - i) % 3 == 0 ? "\u202F" : "") + std::string(1, digits[i]);
  return text;
}

}  // namespace dlpverify::plot

void dlpverify::check_plot_path(const std::string& option, const std::string& path) {
  plot::figure_format(option, path);
  check_output_path(option, path);
}
