#include "plot/stability_plot.hpp"

#include "plot/gnuplot_script.hpp"

#include <stdexcept>

namespace dlpverify::plot {

std::string stability_region_figure(const std::vector<std::vector<double>>& grid, const std::string& title,
                                    const std::string& output, const std::string& option) {
  if (grid.empty()) throw std::logic_error("stability_region_figure: an empty grid");
  std::vector<std::vector<double>> stable;  // 1 where |R(z)| ≤ 1, else 0
  stable.reserve(grid.size());
  for (const std::vector<double>& row : grid) stable.push_back({row[0], row[1], row[2] <= 1.0 ? 1.0 : 0.0});
  GnuplotScript script;
  const std::string data = script.table(stable);
  const std::string heading = script.text(title + ": stable where |R(z)| <= 1 (shaded)");
  const std::string re = script.text("Re z"), im = script.text("Im z");
  script.command("set title " + heading + " noenhanced");
  script.command("set xlabel " + re + " noenhanced");
  script.command("set ylabel " + im + " noenhanced");
  script.command("set size ratio -1");
  const std::vector<double>& first = grid.front();
  const std::vector<double>& last = grid.back();  // the grid's corners: the window, no margin
  script.command("set xrange [" + number(first[0]) + ":" + number(last[0]) + "]");
  script.command("set yrange [" + number(first[1]) + ":" + number(last[1]) + "]");
  script.command("set palette defined (0 \"white\", 1 \"steelblue\")");
  script.command("set cbrange [0:1]");
  script.command("unset colorbox");
  script.command("set xzeroaxis lt -1");
  script.command("set yzeroaxis lt -1");
  script.command("set grid front");
  script.command("plot " + data + " using 1:2:3 with image notitle");
  return render_figure(script, 640, 640, output, option);
}

}  // namespace dlpverify::plot
