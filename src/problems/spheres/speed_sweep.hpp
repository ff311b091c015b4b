// The quasi-static limit (docs/model.md §7.2): the error of the ensemble mean T2/T1 against the
// law, |T2/T1 − law|, at several wall speeds, and the slope of ln error against ln speed fitted by
// the harness (dlpverify/order.hpp: the same least squares and 95% interval as an observed order
// against Δt — here the wall speed is the refinement parameter).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "problems/spheres/compression.hpp"
#include "dlpverify/order.hpp"

namespace dlpverify::compress {

// The law a row is measured against, of the compression the centres see, r = accessible_ratio:
// all axes, the monatomic adiabat r^(2/3); one axis, the law of the row's regime ((r² + 2)/3 when
// collisionless, else r^(2/3)). As the walls slow down the error against it falls to zero.
double law_for(const Compression& c, const EnsembleRow& row);

struct SweepPoint {
  double parameter = 0.0;         // the refinement parameter: wall speed [m/s], or σ/L
  int spheres = 0;
  EnsembleRow row;
  double law = 0.0, error = 0.0;  // |mean − law|
  bool resolved = false;          // error > 2 standard errors: above the ensemble's noise
};

struct SweepRatio {
  double volume_ratio = 0.0;
  std::vector<SweepPoint> points;  // in the order of the parameters given
  OrderFit fit;                    // slope of ln error against ln parameter over the resolved points
};

std::vector<SweepRatio> sweep_wall_speeds(Compression c, const std::vector<double>& volume_ratios,
                                          const std::vector<double>& wall_speeds, int runs, std::uint64_t seed);

// The dense gas against the Carnahan–Starling adiabat (all axes): at a fixed packing fraction η
// (V = L³), ensembles of more and more spheres, each of radius radius_for_packing(N, η, L). The
// walls' excluded layer makes a finite box differ from the bulk fluid by O(σ/L); the error
// |T2/T1 − CS| against σ/L and its fitted slope show whether it vanishes as N grows.
std::vector<SweepRatio> sweep_sizes(Compression c, double packing, const std::vector<double>& volume_ratios,
                                    const std::vector<int>& spheres, int runs, std::uint64_t seed);

}  // namespace dlpverify::compress
