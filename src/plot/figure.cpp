#include "plot/figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "plot/gnuplot_script.hpp"

namespace dlpverify::plot {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Margins of every panel, in gnuplot character units (so they scale with the font).
constexpr double kLeftMargin = 11.5, kRightMargin = 3.0, kBottomMargin = 3.6, kTopMargin = 2.6;

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
  bool empty() const { return !(lo <= hi); }
  double span() const { return hi - lo; }
};

// Data extent plus a margin, so no point sits on the frame.
Range padded(Range r, Scale scale, double fraction) {
  if (r.empty()) return scale == Scale::log ? Range{-3.0, 0.0} : Range{0.0, 1.0};
  if (r.span() <= 0.0) {
    const double half = scale == Scale::log ? 0.5 : std::max(std::abs(r.lo), 1.0) * 0.1;
    return {r.lo - half, r.hi + half};
  }
  const double pad = std::max(fraction * r.span(), scale == Scale::log ? 0.06 : 0.0);
  return {r.lo - pad, r.hi + pad};
}

bool connected(const Element& e) { return e.style.find("lines") != std::string::npos; }

// Where a point is drawn, in axis coordinates; nullopt when it is not drawn at all.
struct Placed {
  double x, y;
  Pin pin;  // none, top or bottom
};

std::vector<Placed> place(const Element& e, const Panel& panel, const Range& y) {
  std::vector<Placed> out;
  for (const auto& row : e.rows) {
    if (row.empty() || !on_axis(row[0], panel.x_scale)) continue;
    const double x = to_axis(row[0], panel.x_scale);
    const bool has_y = row.size() > 1 && on_axis(row[1], panel.y_scale);
    switch (e.pin) {
      case Pin::none:
        if (has_y) out.push_back({x, to_axis(row[1], panel.y_scale), Pin::none});
        break;
      case Pin::top:
        out.push_back({x, y.hi, Pin::top});
        break;
      case Pin::bottom:
        out.push_back({x, y.lo, Pin::bottom});
        break;
      case Pin::top_when_off_scale: {
        const double t = has_y ? to_axis(row[1], panel.y_scale) : kInf;
        if (t >= y.lo && t <= y.hi)
          out.push_back({x, t, Pin::none});
        else
          out.push_back({x, y.hi, Pin::top});
        break;
      }
    }
  }
  return out;
}

// Text metrics of gnuplot's cairo terminals with DejaVu Sans at 96 dpi, a little generous.
// The svg terminal's character cell is about 1.2 times as tall as the cairo terminals'.
struct Metrics {
  double char_px, line_px;
  Metrics(double font_points, FigureFormat format)
      : char_px(0.62 * font_points * 96.0 / 72.0),
        line_px(1.3 * font_points * 96.0 / 72.0 * (format == FigureFormat::svg ? 1.2 : 1.0)) {}
};

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

struct KeyChoice {
  std::string command;
  Range y;
};

// The legend goes in the corner where it covers nothing, stretching the y range (on the side of
// that corner) until the data clear its box: the corner that needs the least stretch wins, ties
// going to the panel's preference. A corner whose edge holds pinned points (an unstable level on
// the top edge, a zero error on the bottom one) is taken only when every corner has some.
KeyChoice place_key(const Panel& panel, const std::vector<Placed>& marks, const Range& x, const Range& y, int lines,
                    std::size_t longest, double plot_width_px, double plot_height_px, const Metrics& m) {
  const std::string style = " opaque box lc rgb \"#bbbbbb\" lw 1 samplen 2.2 spacing 1.1 width 1 height 0.6 reverse Left";
  if (lines == 0) return {"unset key", y};
  const double key_width = ((2.2 + 3.0) * m.char_px + static_cast<double>(longest) * m.char_px) / plot_width_px;
  const double key_height = ((lines * 1.15 + 1.0) * m.line_px) / plot_height_px;
  // Wider than the axes, or nearly as tall: only below them does it fit.
  if (key_width >= 0.95 || key_height >= 0.85) return {"set key below center horizontal" + style, y};

  for (bool respect_pins : {true, false}) {
    double best_cost = kInf;
    KeyChoice best{"", y};
    for (Corner corner : panel.key_preference) {
      const bool top = corner == Corner::top_left || corner == Corner::top_right;
      const bool left = corner == Corner::top_left || corner == Corner::bottom_left;
      Range stretched = y;
      bool feasible = true;
      const double clear = 1.0 - key_height - 0.03;
      for (const auto& p : marks) {
        const double fx = (p.x - x.lo) / x.span();
        const bool under_key = left ? fx <= key_width + 0.02 : fx >= 1.0 - key_width - 0.02;
        if (!under_key) continue;
        if ((top && p.pin == Pin::top) || (!top && p.pin == Pin::bottom)) {
          feasible = feasible && !respect_pins;
          continue;
        }
        if (p.pin != Pin::none) continue;
        if (top)
          stretched.hi = std::max(stretched.hi, y.lo + (p.y - y.lo) / clear);
        else
          stretched.lo = std::min(stretched.lo, y.hi - (y.hi - p.y) / clear);
      }
      if (!feasible) continue;
      const double cost = (stretched.span() - y.span()) / y.span();
      if (cost < best_cost - 0.02) {
        best_cost = cost;
        const char* where = corner == Corner::top_left      ? "top left"
                            : corner == Corner::top_right   ? "top right"
                            : corner == Corner::bottom_left ? "bottom left"
                                                            : "bottom right";
        best = {std::string("set key inside ") + where + style, stretched};
      }
    }
    if (std::isfinite(best_cost)) return best;
  }
  return {"set key inside top left" + style, y};
}

// Tics of a log axis: decades labelled 10^k when the range spans three or more; otherwise
// 1-2-5 (or finer) tics labelled m×10^k, with minor tics at the other integer mantissas.
void log_tics(GnuplotScript& s, const std::string& axis, double lo, double hi) {
  const double decades = std::log10(hi / lo);
  // Counts (RHS evaluations, steps) read better as 50, 100, 200 than as 5×10^1.
  const bool plain = lo >= 1.0 && hi <= 1e5;
  if (decades >= 3.0) {
    s.command("set format " + axis + (plain ? " \"%g\"" : " \"10^{%L}\""));
    s.command("set " + axis + "tics autofreq");
    s.command("set m" + axis + "tics default");
    return;
  }
  const auto tics_with = [&](const std::vector<double>& mantissas) {
    std::vector<std::pair<double, std::string>> tics;
    for (int k = static_cast<int>(std::floor(std::log10(lo))) - 1; k <= static_cast<int>(std::ceil(std::log10(hi))) + 1; ++k)
      for (double mantissa : mantissas) {
        const double v = mantissa * std::pow(10.0, k);
        if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9)) continue;
        tics.emplace_back(v, plain ? format("%g", v) : mantissa == 1.0 ? format("10^{%d}", k) : format("%g×10^{%d}", mantissa, k));
      }
    return tics;
  };
  auto tics = tics_with({1, 2, 5});
  if (tics.size() < 3) tics = tics_with({1, 1.5, 2, 3, 4, 5, 6, 8});
  std::string list;
  for (const auto& [value, label] : tics) list += (list.empty() ? "" : ", ") + s.text(label) + " " + number(value);
  // Minor tics at every integer mantissa that is not a major tic.
  std::string minor;
  for (int k = static_cast<int>(std::floor(std::log10(lo))); k <= static_cast<int>(std::ceil(std::log10(hi))); ++k)
    for (int mantissa = 1; mantissa <= 9; ++mantissa) {
      const double v = mantissa * std::pow(10.0, k);
      if (v < lo || v > hi) continue;
      const bool major = std::any_of(tics.begin(), tics.end(), [&](const auto& t) { return std::abs(t.first / v - 1) < 1e-9; });
      if (!major) minor += ", \"\" " + number(v) + " 1";
    }
  s.command("set format " + axis + " \"%g\"");
  s.command("unset m" + axis + "tics");
  s.command("set " + axis + "tics (" + list + minor + ")");
}

void axis_commands(GnuplotScript& s, const std::string& axis, Scale scale, double lo, double hi) {
  s.command(std::string(scale == Scale::log ? "set" : "unset") + " logscale " + axis);
  s.command("set " + axis + "range [" + number(lo) + ":" + number(hi) + "]");
  if (scale == Scale::log) {
    log_tics(s, axis, lo, hi);
  } else {
    s.command("set format " + axis + " \"%g\"");
    s.command("set " + axis + "tics autofreq");
    s.command("set m" + axis + "tics default");
  }
}

}  // namespace

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

std::string join_distinct(const std::vector<std::string>& items) {
  std::vector<std::string> seen;
  std::string text;
  for (const auto& item : items)
    if (std::find(seen.begin(), seen.end(), item) == seen.end()) {
      seen.push_back(item);
      text += (text.empty() ? "" : ", ") + item;
    }
  return text;
}

std::string unit_list(const std::vector<std::string>& variables) {
  std::vector<std::string> units;
  for (const auto& v : variables)
    if (!variable_unit(v).empty()) units.push_back(variable_unit(v));
  return join_distinct(units);
}

std::vector<std::string> canonical_variable_order(std::vector<std::string> names) {
  static const std::array<std::string, 4> known = {"position", "velocity", "temperature", "mass"};
  std::vector<std::string> ordered;
  for (const auto& k : known)
    if (std::find(names.begin(), names.end(), k) != names.end()) ordered.push_back(k);
  for (const auto& n : names)
    if (std::find(ordered.begin(), ordered.end(), n) == ordered.end()) ordered.push_back(n);
  return ordered;
}

std::string grouped_digits(long long value) {
  const std::string digits = std::to_string(value < 0 ? -value : value);
  std::string text = value < 0 ? "-" : "";
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += "\u202F";
    text += digits[i];
  }
  return text;
}

void lay_out(Figure& figure, int panel_width, int panel_height) {
  const int n = std::max<int>(1, static_cast<int>(figure.panels.size()));
  figure.rows = n <= 3 ? 1 : 2;
  figure.columns = (n + figure.rows - 1) / figure.rows;
  figure.canvas.width = panel_width * figure.columns;
  figure.canvas.height = panel_height * figure.rows + (n > 1 ? 40 : 0);
}

void draw(const Figure& figure, const std::string& output, const std::string& option) {
  if (figure.panels.empty()) throw std::logic_error("a figure without panels");

  GnuplotScript s;
  const FigureFormat format = figure_format(option, output);
  const Metrics metrics(figure.canvas.font_points, format);
  const double font_scale = terminal_scale(format).font;
  const auto font = [&](double points) { return "font \"," + number(std::round(points * font_scale * 10) / 10) + "\""; };
  const bool several = figure.panels.size() > 1;
  const double title_px = several ? 2.2 * metrics.line_px : 0.0;
  const double panel_width_px = static_cast<double>(figure.canvas.width) / figure.columns;
  const double panel_height_px = (figure.canvas.height - title_px) / figure.rows;

  s.command("set grid xtics ytics mxtics mytics back lt 1 lw 0.8 lc rgb \"#d9d9d9\", lt 1 lw 0.5 lc rgb \"#eeeeee\"");
  s.command("set border lw 1 lc rgb \"#404040\"");
  // `set tics` would switch on x2 and y2 tics too: each axis on its own.
  s.command("unset x2tics");
  s.command("unset y2tics");
  s.command("set xtics in mirror scale 0.9, 0.45 tc rgb \"#202020\"");
  s.command("set ytics in mirror scale 0.9, 0.45 tc rgb \"#202020\"");
  s.command("set lmargin " + number(kLeftMargin));
  s.command("set rmargin " + number(kRightMargin));
  if (several)
    s.command("set multiplot layout " + std::to_string(figure.rows) + "," + std::to_string(figure.columns) + " title " +
              s.text(figure.title) + " noenhanced " + font(figure.canvas.font_points + 2));

  // First every panel's ranges and legend, then (a shared y range known) their commands.
  struct Layout {
    Range x, y;
    Range data_y;  // before the legend's stretch: decides which points are off scale
    KeyChoice key;
    double top_margin, bottom_margin;
  };
  std::vector<Layout> layouts;
  for (const auto& panel : figure.panels) {
    // Ranges from the data that sets them; pinned points only widen x.
    Range x, y;
    for (const auto& e : panel.elements) {
      if (e.key_only) continue;
      for (const auto& row : e.rows) {
        if (row.empty() || !on_axis(row[0], panel.x_scale)) continue;
        x.add(to_axis(row[0], panel.x_scale));
        if (e.pin == Pin::none && row.size() > 1 && on_axis(row[1], panel.y_scale)) y.add(to_axis(row[1], panel.y_scale));
      }
    }
    for (const auto& label : panel.labels)
      if (on_axis(label.x, panel.x_scale) && on_axis(label.y, panel.y_scale)) {
        x.add(to_axis(label.x, panel.x_scale));
        y.add(to_axis(label.y, panel.y_scale));
      }
    x = padded(x, panel.x_scale, 0.05);
    y = padded(y, panel.y_scale, 0.06);

    // Everything drawn, for the legend's placement: points, line samples, label extents.
    std::vector<Placed> marks;
    for (const auto& e : panel.elements) {
      if (e.key_only) continue;
      const auto placed = place(e, panel, y);
      marks.insert(marks.end(), placed.begin(), placed.end());
      if (connected(e))
        for (std::size_t i = 1; i < placed.size(); ++i)
          for (int k = 1; k < 16; ++k) {
            const double f = k / 16.0;
            marks.push_back({placed[i - 1].x + f * (placed[i].x - placed[i - 1].x),
                             placed[i - 1].y + f * (placed[i].y - placed[i - 1].y), Pin::none});
          }
    }
    const double plot_width_px = panel_width_px - (kLeftMargin + kRightMargin) * metrics.char_px;
    const double top_margin = kTopMargin + (several ? 0.8 : 0.6);
    const double bottom_margin = kBottomMargin + (panel.note.empty() ? 0.0 : 1.1);
    const double plot_height_px = panel_height_px - (top_margin + bottom_margin) * metrics.line_px;
    for (const auto& label : panel.labels) {
      if (!on_axis(label.x, panel.x_scale) || !on_axis(label.y, panel.y_scale)) continue;
      const double lx = to_axis(label.x, panel.x_scale), ly = to_axis(label.y, panel.y_scale);
      const double width = (code_points(label.text) + 1.5) * metrics.char_px / plot_width_px * x.span();
      for (int k = 0; k <= 4; ++k) marks.push_back({lx + width * k / 4.0, ly, Pin::none});
    }
    int key_lines = 0;
    std::size_t longest = 0;
    for (const auto& e : panel.elements)
      if (!e.title.empty()) {
        ++key_lines;
        longest = std::max(longest, code_points(e.title));
      }
    const KeyChoice key = panel.key ? place_key(panel, marks, x, y, key_lines, longest, plot_width_px, plot_height_px, metrics)
                                    : KeyChoice{"unset key", y};
    layouts.push_back({x, key.y, y, key, top_margin, bottom_margin});
  }
  if (figure.shared_y) {
    Range all;
    for (const auto& l : layouts) {
      all.add(l.y.lo);
      all.add(l.y.hi);
    }
    for (auto& l : layouts) l.y = all;
  }

  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const Panel& panel = figure.panels[p];
    const Range& x = layouts[p].x;
    const Range& y = layouts[p].y;
    const KeyChoice& key = layouts[p].key;
    const double top_margin = layouts[p].top_margin, bottom_margin = layouts[p].bottom_margin;
    s.command("unset label");
    s.command("set tmargin " + number(top_margin));
    s.command("set bmargin " + number(bottom_margin));
    axis_commands(s, "x", panel.x_scale, from_axis(x.lo, panel.x_scale), from_axis(x.hi, panel.x_scale));
    axis_commands(s, "y", panel.y_scale, from_axis(y.lo, panel.y_scale), from_axis(y.hi, panel.y_scale));
    s.command("set xlabel " + s.text(panel.x_label) + " noenhanced offset 0,0.3");
    s.command("set ylabel " + s.text(panel.y_label) + " noenhanced offset 0.5,0");
    const std::string& title = several ? panel.title : (panel.title.empty() ? figure.title : panel.title);
    if (title.empty())
      s.command("unset title");
    else
      s.command("set title " + s.text(title) + " noenhanced " + font(figure.canvas.font_points + (several ? 1 : 2)));
    s.command(key.command);
    int tag = 1;
    for (const auto& label : panel.labels)
      s.command("set label " + std::to_string(tag++) + " " + s.text(label.text) + " at first " + number(label.x) +
                ", first " + number(label.y) + " left offset character 0.4,0 tc rgb \"" + label.colour + "\" noenhanced front");
    if (!panel.note.empty())
      s.command("set label " + std::to_string(tag++) + " " + s.text(panel.note) +
                " at graph 1, graph 0 right offset 0,-3.4 tc rgb \"#555555\" " + font(figure.canvas.font_points - 2) +
                " noenhanced");

    std::string plot;
    for (const auto& e : panel.elements) {
      std::string item;
      if (e.key_only) {
        item = "keyentry " + e.style;
      } else {
        std::vector<std::vector<double>> rows;
        for (const auto& pt : place(e, panel, layouts[p].data_y))
          rows.push_back({from_axis(pt.x, panel.x_scale), from_axis(pt.pin == Pin::top      ? y.hi - 0.012 * y.span()
                                                                    : pt.pin == Pin::bottom ? y.lo + 0.012 * y.span()
                                                                                            : pt.y,
                                                                    panel.y_scale)});
        if (rows.empty() && e.title.empty()) continue;
        if (rows.empty()) rows.push_back({std::nan(""), std::nan("")});
        item = s.table(rows) + " using 1:2 " + e.style;
      }
      item += e.title.empty() ? " notitle" : " title " + s.text(e.title) + " noenhanced";
      plot += (plot.empty() ? "plot " : ", ") + item;
    }
    // gnuplot needs one plot with data even when there is nothing to show.
    if (plot.empty() || plot.find("using") == std::string::npos)
      plot += (plot.empty() ? "plot " : ", ") + s.table({{std::nan(""), std::nan("")}}) + " using 1:2 with points notitle";
    s.command(plot);
  }
  if (several) s.command("unset multiplot");

  render_figure(s, figure.canvas, output, option);
}

}  // namespace dlpverify::plot
