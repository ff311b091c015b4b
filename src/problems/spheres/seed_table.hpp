// The seed's published result (docs/model.md §7.2, its table 1): the seven compressions, walls
// at half-edges 3.8 … 2.6 m of the 8 m cube, with T2/T1 from the ideal-gas law and from the
// author's simulation, both rounded to two decimals as published.
#pragma once

#include <array>
#include <cmath>

namespace dlpverify::compress {

struct SeedRow {
  double half_edge;          // m, after the compression
  double published_ratio;    // V1/V2 as printed
  double analytic, simulated;
};

inline constexpr std::array<SeedRow, 7> kSeedTable = {{{3.8, 1.17, 1.11, 1.11},
                                                       {3.6, 1.37, 1.23, 1.23},
                                                       {3.4, 1.63, 1.38, 1.38},
                                                       {3.2, 1.95, 1.56, 1.57},
                                                       {3.0, 2.37, 1.78, 1.78},
                                                       {2.8, 2.92, 2.04, 2.04},
                                                       {2.6, 3.64, 2.37, 2.38}}};

// V1/V2 exactly, (4 m / half-edge)³.
inline double seed_volume_ratio(const SeedRow& row) { return std::pow(4.0 / row.half_edge, 3); }

}  // namespace dlpverify::compress
