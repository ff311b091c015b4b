// The quasi-static limit (docs/model.md §7.2): the error of the ensemble mean T2/T1 against the
// law, |T2/T1 − law|, at several wall speeds, and the slope of ln error against ln speed fitted by
// the harness (dlpverify/order.hpp: the same least squares and 95% interval as an observed order
// against Δt — here the wall speed is the refinement parameter).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compress/compression.hpp"
#include "dlpverify/order.hpp"

namespace dlpverify::compress {

// The law a row is measured against: all axes, the monatomic adiabat r^(2/3); one axis, the
// law of the row's regime ((r² + 2)/3 when collisionless, else r^(2/3)).
double law_for(const Compression& c, const EnsembleRow& row);

struct SweepPoint {
  double wall_speed = 0.0;
  EnsembleRow row;
  double law = 0.0, error = 0.0;  // |mean − law|
  bool resolved = false;          // error > 2 standard errors: above the ensemble's noise
};

struct SweepRatio {
  double volume_ratio = 0.0;
  std::vector<SweepPoint> points;  // in the order of the speeds given
  OrderFit fit;                    // slope of ln error against ln speed over the resolved points
};

std::vector<SweepRatio> sweep_wall_speeds(Compression c, const std::vector<double>& volume_ratios,
                                          const std::vector<double>& wall_speeds, int runs, std::uint64_t seed);

}  // namespace dlpverify::compress
