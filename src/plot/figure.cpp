#include "plot/figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/plot.hpp"

namespace dlpverify::plot {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Canvas of one panel alone, and of each panel of several, in pixels.
constexpr int kWidth = 1100, kHeight = 760, kPanelWidth = 760, kPanelHeight = 640;
// What a panel's title, tic labels and axis label leave of its height, and the height of one
// legend line (13-point text at 96 dpi, with gnuplot's spacing): a rule of thumb, not a metric.
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

// The data's extent plus a margin, so no point sits on the frame; a default when there is none.
Range padded(Range r, Scale scale, double fraction) {
  if (!(r.lo <= r.hi)) return scale == Scale::log ? Range{-3.0, 0.0} : Range{0.0, 1.0};
  if (r.span() <= 0.0) {
    const double half = scale == Scale::log ? 0.5 : std::max(std::abs(r.lo), 1.0) * 0.1;
    return {r.lo - half, r.hi + half};
  }
  const double pad = std::max(fraction * r.span(), scale == Scale::log ? 0.06 : 0.0);
  return {r.lo - pad, r.hi + pad};
}

// In axis coordinates: x and y as drawn, and data_y, the data's own y range, which decides what
// is off scale.
struct Ranges {
  Range x, y, data_y;
};

// Ranges from the data (pinned points only widen x) and labels; then the legend's rule: the y
// range grows upwards until the data keep the lower 1 − f of the axes, f the legend's share of
// the height, so the legend at the top covers nothing.
Ranges ranges_of(const Panel& p, double plot_height_px) {
  Range x, y;
  int key_lines = 0;
  for (const auto& e : p.elements) {
    key_lines += !e.title.empty();
    if (e.key_only) continue;
    for (const auto& row : e.rows) {
      if (row.size() < 2 || !on_axis(row[0], p.x_scale)) continue;
      x.add(to_axis(row[0], p.x_scale));
      if (e.pin == Pin::none && on_axis(row[1], p.y_scale)) y.add(to_axis(row[1], p.y_scale));
    }
  }
  for (const auto& label : p.labels)
    if (on_axis(label.x, p.x_scale) && on_axis(label.y, p.y_scale)) {
      x.add(to_axis(label.x, p.x_scale));
      y.add(to_axis(label.y, p.y_scale));
    }
  Ranges r{padded(x, p.x_scale, 0.05), padded(y, p.y_scale, 0.06), {}};
  r.data_y = r.y;
  for (const auto& label : p.labels)  // room for the text right of a label's position
    if (on_axis(label.x, p.x_scale)) r.x.hi = std::max(r.x.hi, to_axis(label.x, p.x_scale) + 0.16 * r.x.span());
  if (!p.key.empty() && key_lines > 0) {
    const double f = std::min(0.6, (key_lines + 1.0) * kKeyLinePx / plot_height_px);
    r.y.hi = r.y.lo + r.y.span() / (1.0 - f);
  }
  return r;
}

// The rows of an element as drawn: pinned points just inside their edge, points off a log axis
// (zero, negative, NaN) left out.
std::vector<std::vector<double>> placed(const Element& e, const Panel& p, const Ranges& r) {
  const double top = r.y.hi - 0.012 * r.y.span(), bottom = r.y.lo + 0.012 * r.y.span();
  std::vector<std::vector<double>> rows;
  for (const auto& row : e.rows) {
    if (row.size() < 2 || !on_axis(row[0], p.x_scale)) continue;
    const bool has_y = on_axis(row[1], p.y_scale);
    const double t = has_y ? to_axis(row[1], p.y_scale) : kInf;
    if (e.pin == Pin::none && !has_y) continue;
    const double y = e.pin == Pin::none     ? t
                     : e.pin == Pin::bottom ? bottom
                     : e.pin == Pin::top || t < r.data_y.lo || t > r.data_y.hi ? top
                                                                                 : t;
    rows.push_back({row[0], from_axis(y, p.y_scale)});
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
  for (int k = static_cast<int>(std::floor(std::log10(lo))); scale == Scale::log && hi / lo < 1e3 && k <= std::log10(hi); ++k)
    for (int m = 1; m <= 9; ++m) {
      const double v = m * std::pow(10.0, k);
      const bool major = m == 1 || m == 2 || m == 5;
      const std::string label = counts ? format("%g", v) : m == 1 ? format("10^{%d}", k) : format("%d×10^{%d}", m, k);
      if (v < lo || v > hi) continue;
      tics += tics.empty() ? "(" : ", ";
      tics += (major ? s.text(label) + " " : "\"\" ") + number(v) + (major ? "" : " 1");
    }
  s.command("set " + a + "tics " + (tics.empty() ? std::string("autofreq") : tics + ")"));
}

// The plot command of a panel: every element's data as a datablock, every legend entry as text.
std::string plot_command(GnuplotScript& s, const Panel& p, const Ranges& r) {
  const double nan = std::nan("");
  std::string plot;
  for (const auto& e : p.elements) {
    std::string item = "keyentry " + e.style;
    if (!e.key_only) {
      auto rows = placed(e, p, r);
      if (rows.empty() && e.title.empty()) continue;
      if (rows.empty()) rows.push_back({nan, nan});  // nothing to draw, but its legend entry
      item = s.table(rows) + " using 1:2 " + e.style;
    }
    item += e.title.empty() ? " notitle" : " title " + s.text(e.title) + " noenhanced";
    plot += (plot.empty() ? "plot " : ", ") + item;
  }
  // gnuplot needs one item with data even when there is nothing to show.
  if (plot.find(" using ") == std::string::npos)
    plot += (plot.empty() ? "plot " : ", ") + s.table({{nan, nan}}) + " using 1:2 with points notitle";
  return plot;
}

void panel_commands(GnuplotScript& s, const Figure& figure, const Panel& p, const Ranges& r, bool several) {
  s.command("unset label");
  s.command("set tmargin " + number(several ? 3.4 : 3.2));
  s.command("set bmargin " + number(p.note.empty() ? 3.6 : 4.7));
  axis(s, "x", p.x_scale, r.x);
  axis(s, "y", p.y_scale, r.y);
  s.command("set xlabel " + s.text(p.x_label) + " noenhanced offset 0,0.3");
  s.command("set ylabel " + s.text(p.y_label) + " noenhanced offset 0.5,0");
  const std::string& title = several || !p.title.empty() ? p.title : figure.title;
  s.command(title.empty() ? "unset title" : "set title " + s.text(title) + " noenhanced font \"," + (several ? "14" : "15") + "\"");
  s.command(p.key.empty() ? "unset key"
                          : "set key inside " + p.key + " opaque box lc rgb \"#bbbbbb\" samplen 2.2 spacing 1.1 reverse Left");
  int tag = 1;
  for (const auto& l : p.labels)
    s.command("set label " + std::to_string(tag++) + " " + s.text(l.text) + " at first " + number(l.x) + ", first " +
              number(l.y) + " left offset character 0.4,0 tc rgb \"" + l.colour + "\" noenhanced front");
  if (!p.note.empty())
    s.command("set label " + std::to_string(tag) + " " + s.text(p.note) +
              " at graph 1, graph 0 right offset 0,-3.4 tc rgb \"#555555\" font \",11\" noenhanced");
  s.command(plot_command(s, p, r));
}

}  // namespace

void draw(const Figure& figure, const std::string& output, const std::string& option) {
  if (figure.panels.empty()) throw std::logic_error("a figure without panels");
  figure_format(option, output);  // a bad name fails before any work
  const int n = static_cast<int>(figure.panels.size());
  const bool several = n > 1;
  const int rows = n <= 3 ? 1 : 2, columns = (n + rows - 1) / rows;
  const int panel_height = several ? kPanelHeight : kHeight;

  std::vector<Ranges> ranges;
  for (const auto& panel : figure.panels) ranges.push_back(ranges_of(panel, panel_height - kFramePx));
  if (figure.shared_y) {
    Range all;
    for (const auto& r : ranges) {
      all.add(r.y.lo);
      all.add(r.y.hi);
    }
    for (auto& r : ranges) r.y = all;
  }

  GnuplotScript s;
  s.command("set grid xtics ytics mxtics mytics back lt 1 lw 0.8 lc rgb \"#d9d9d9\", lt 1 lw 0.5 lc rgb \"#eeeeee\"");
  s.command("set border lw 1 lc rgb \"#404040\"");
  s.command("set xtics in mirror scale 0.9, 0.45 tc rgb \"#202020\"");
  s.command("set ytics in mirror scale 0.9, 0.45 tc rgb \"#202020\"");
  // Fixed side margins: panels side by side line up.
  s.command("set lmargin 11.5");
  s.command("set rmargin 3");
  if (several)
    s.command("set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) + " title " +
              s.text(figure.title) + " noenhanced font \",15\"");
  for (std::size_t p = 0; p < figure.panels.size(); ++p) panel_commands(s, figure, figure.panels[p], ranges[p], several);
  if (several) s.command("unset multiplot");
  render_figure(s, (several ? kPanelWidth : kWidth) * columns, panel_height * rows + (several ? 40 : 0), output, option);
}

std::string series_colour(std::size_t index) {
  static constexpr std::array colours = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#8C564B"};
  return colours[index % colours.size()];
}

std::string variable_unit(const std::string& variable) {
  if (variable == "position") return "m";
  if (variable == "velocity") return "m/s";
  if (variable == "temperature") return "K";
  if (variable == "mass") return "kg";
  return "";
}

std::string with_unit(const std::string& variable) {
  const std::string unit = variable_unit(variable);
  return unit.empty() ? variable : variable + " [" + unit + "]";
}

std::string join_distinct(const std::vector<std::string>& items) {
  std::string text;
  for (auto it = items.begin(); it != items.end(); ++it)
    if (std::find(items.begin(), it, *it) == it) text += (text.empty() ? "" : ", ") + *it;
  return text;
}

std::string unit_list(const std::vector<std::string>& variables) {
  std::vector<std::string> units;
  for (const auto& v : variables)
    if (!variable_unit(v).empty()) units.push_back(variable_unit(v));
  return join_distinct(units);
}

std::vector<std::string> canonical_variable_order(std::vector<std::string> names) {
  std::vector<std::string> ordered;
  for (const char* known : {"position", "velocity", "temperature", "mass"})
    if (std::find(names.begin(), names.end(), known) != names.end()) ordered.push_back(known);
  for (const auto& n : names)
    if (std::find(ordered.begin(), ordered.end(), n) == ordered.end()) ordered.push_back(n);
  return ordered;
}

std::string distinct_label(const std::vector<std::string>& names, const std::vector<std::string>& cases, std::size_t i,
                           std::size_t number) {
  std::size_t same_name = 0, same_case = 0;
  for (std::size_t k = 0; k < names.size(); ++k) {
    same_name += names[k] == names[i];
    same_case += names[k] == names[i] && cases[k] == cases[i];
  }
  if (same_name < 2) return names[i];
  return names[i] + " · " + cases[i] + (same_case > 1 ? " #" + std::to_string(number) : "");
}

std::string grouped_digits(long long value) {
  const std::string digits = std::to_string(value < 0 ? -value : value);
  std::string text = value < 0 ? "-" : "";
  for (std::size_t i = 0; i < digits.size(); ++i) text += (i > 0 && (digits.size() - i) % 3 == 0 ? "\u202F" : "") + std::string(1, digits[i]);
  return text;
}

}  // namespace dlpverify::plot

namespace dlpverify {

void check_plot_path(const std::string& option, const std::string& path) {
  plot::figure_format(option, path);
  check_output_path(option, path);
}

}  // namespace dlpverify
