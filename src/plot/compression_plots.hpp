// Figures of `dlpverify compress` results (docs/model.md §7.2), from the result JSON alone:
//   rows  → T2/T1 against V1/V2 (linear x, log y): the ensemble means as points beside the
//           monatomic adiabat (V1/V2)^(2/3), the Carnahan–Starling adiabat (all axes, when the
//           gas is not dilute), the collisionless law (r² + 2)/3 (one axis), the seed's table
//   sweep → |T2/T1 − law| against wall speed (log–log), a colour per ratio, its fitted line
#pragma once

#include <nlohmann/json.hpp>

#include "plot/figure.hpp"
#include "plot/plot.hpp"

namespace dlpverify {

plot::Figure compression_figure(const nlohmann::json& result, const PlotOptions& options);
std::string plot_compression(const nlohmann::json& result, const PlotOptions& options);

}  // namespace dlpverify
