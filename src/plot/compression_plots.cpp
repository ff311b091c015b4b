#include "plot/compression_plots.hpp"

#include <algorithm>
#include <cmath>

#include "problems/spheres/adiabats.hpp"
#include "problems/spheres/seed_table.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"

namespace dlpverify {

namespace {

using plot::Element;
using plot::Panel;

std::string colour(std::size_t i) { return " lc rgb \"" + plot::series_colour(i) + "\""; }

// A law as a curve over [1, r_max], 100 points.
Element curve(double r_max, double (*law)(double, double), double parameter, const std::string& title, std::size_t c,
              const char* dash) {
  Element e{.style = std::string("with lines lw 2 ") + dash + colour(c), .title = title};
  for (int k = 0; k <= 100; ++k) {
    const double r = 1.0 + (r_max - 1.0) * k / 100.0;
    e.rows.push_back({r, law(r, parameter)});
  }
  return e;
}

Panel rows_panel(const nlohmann::json& result) {
  const nlohmann::json& settings = result.at("settings");
  const int axes = settings.at("axes");
  const double packing = settings.at("packing_fraction");
  Panel p{.x_label = axes == 3 ? "V1/V2" : "V1/V2 = L1/L2 (one axis)", .y_label = "T2/T1", .x_scale = plot::Scale::linear};
  double r_max = 1.0;
  Element simulated{.style = "with points pt 7 ps 1.5" + colour(0),
                    .title = "simulated, mean of " + std::to_string(settings.at("runs").get<int>()) + " runs"};
  for (const auto& row : result.at("rows")) {
    r_max = std::max(r_max, row.at("volume_ratio").get<double>());
    simulated.rows.push_back({row.at("volume_ratio").get<double>(), row.at("simulated").get<double>()});
  }
  p.elements.push_back(curve(r_max, [](double r, double) { return compress::ideal_adiabat(r); }, 0.0,
                             "ideal gas (V1/V2)^(2/3)", 6, "dt 1"));
  if (axes == 1)
    p.elements.push_back(curve(r_max, [](double r, double) { return compress::collisionless_one_axis(r); }, 0.0,
                               "collisionless (r^2 + 2)/3", 1, "dt 2"));
  if (axes == 3 && packing >= 1e-3 && packing * r_max < 1.0)
    p.elements.push_back(curve(r_max, [](double r, double eta) { return compress::carnahan_starling_adiabat(eta, r); },
                               packing, printf_string("Carnahan-Starling adiabat from eta = %.3g", packing), 2, "dt 3"));
  p.elements.push_back(simulated);
  if (axes == 3 && result.at("rows").size() == compress::kSeedTable.size()) {
    Element seed{.style = "with points pt 6 ps 2.2" + colour(3), .title = "Harrison's table 1 (simulated)"};
    for (std::size_t i = 0; i < compress::kSeedTable.size(); ++i)
      if (std::fabs(result.at("rows")[i].at("volume_ratio").get<double>() /
                        compress::seed_volume_ratio(compress::kSeedTable[i]) - 1.0) < 1e-9)
        seed.rows.push_back({compress::seed_volume_ratio(compress::kSeedTable[i]), compress::kSeedTable[i].simulated});
    if (seed.rows.size() == compress::kSeedTable.size()) p.elements.push_back(seed);
  }
  return p;
}

// A colour per ratio: the fitted points filled, the points within the ensemble's noise (not fitted)
// hollow, the fitted power law over the fitted points' range.
Panel sweep_panel(const nlohmann::json& result) {
  const bool sizes = result.value("sweep_parameter", "") == "sigma_over_edge";
  Panel p{.x_label = sizes ? "sphere diameter / box edge" : "wall speed [m/s]",
          .y_label = sizes ? "|T2/T1 - Carnahan-Starling|" : "|T2/T1 - law(R)|", .x_scale = plot::Scale::log};
  std::size_t c = 0;
  bool any_noise = false;
  for (const auto& ratio : result.at("sweep")) {
    Element fitted{.style = "with points pt 7 ps 1.3" + colour(c)}, noise{.style = "with points pt 6 ps 1.3" + colour(c)};
    const auto& points = ratio.at("points");
    const auto& used = ratio.at("fitted_points");
    double sum_u = 0.0, sum_e = 0.0, u_min = INFINITY, u_max = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const double u = points[k].at("parameter"), e = points[k].at("error");
      const bool in_fit = std::find(used.begin(), used.end(), static_cast<int>(k)) != used.end();
      (in_fit ? fitted : noise).rows.push_back({u, e});
      if (in_fit) sum_u += std::log(u), sum_e += std::log(e), u_min = std::min(u_min, u), u_max = std::max(u_max, u);
    }
    const double r = ratio.at("volume_ratio");
    if (ratio.at("slope").is_number()) {
      const double slope = ratio.at("slope"), lu = sum_u / used.size(), le = sum_e / used.size();
      Element line{.style = "with lines lw 2" + colour(c), .title = printf_string("V1/V2 = %.2f: slope %.2f", r, slope)};
      for (double u : {u_min, u_max}) line.rows.push_back({u, std::exp(le + slope * (std::log(u) - lu))});
      p.elements.push_back(line);
    } else {
      fitted.title = printf_string("V1/V2 = %.2f (no slope: noise)", r);
    }
    p.elements.push_back(fitted);
    any_noise = any_noise || !noise.rows.empty();
    p.elements.push_back(noise);
    ++c;
  }
  if (any_noise)
    p.elements.push_back({.style = "with points pt 6 ps 1.3 lc rgb \"#555555\"", .title = "within 2 standard errors: not fitted"});
  return p;
}

}  // namespace

plot::Figure compression_figure(const nlohmann::json& result, const PlotOptions& options) {
  if (!result.contains("settings") || !(result.contains("rows") || result.contains("sweep")))
    throw InputError(options.option, options.output, "the result is not a `dlpverify compress` table or sweep");
  plot::Figure figure{.title = options.title};
  figure.panels.push_back(result.contains("sweep") ? sweep_panel(result) : rows_panel(result));
  const nlohmann::json& settings = result.at("settings");
  if (figure.title.empty() && result.value("sweep_parameter", "") == "sigma_over_edge")
    figure.title = printf_string("dense hard-sphere gas at packing fraction %.3g: toward Carnahan-Starling as N grows",
                                 settings.at("packing_fraction").get<double>());
  if (figure.title.empty() && result.contains("sweep"))
    figure.title = printf_string("the quasi-static limit: %d spheres, %s", settings.at("spheres").get<int>(),
                                 settings.at("axes").get<int>() == 3 ? "all axes" : "one axis");
  if (figure.title.empty())
    figure.title = printf_string("hard-sphere compression: %d spheres, %s, walls at %g m/s",
                                 result.at("settings").at("spheres").get<int>(),
                                 result.at("settings").at("axes").get<int>() == 3 ? "all axes" : "one axis",
                                 result.at("settings").at("wall_speed").get<double>());
  return figure;
}

std::string plot_compression(const nlohmann::json& result, const PlotOptions& options) {
  return plot::draw(compression_figure(result, options), options.output, options.option);
}

}  // namespace dlpverify
