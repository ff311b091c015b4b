// The stability region of a Runge–Kutta method, {z : |R(z)| ≤ 1}, as a figure: the grid of |R|
// (integrators/tableau/stability.hpp: stability_grid) shaded where a step does not grow, the
// axes through 0, Re z and Im z to one scale.
#pragma once

#include <string>
#include <vector>

namespace dlpverify::plot {

// What gnuplot drew for `output` (PNG, SVG or PDF by its extension), from rows (Re z, Im z, |R|) on
// a regular grid, titled `title`; `option` names the output in errors.
std::string stability_region_figure(const std::vector<std::vector<double>>& grid, const std::string& title,
                                    const std::string& output, const std::string& option);

}  // namespace dlpverify::plot
