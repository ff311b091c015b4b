#include "problems/spheres/expectation.hpp"

#include <cmath>

#include "problems/spheres/adiabats.hpp"
#include "problems/spheres/gas_setup.hpp"
#include "problems/spheres/regime.hpp"
#include "problems/spheres/seed_table.hpp"
#include "problems/spheres/speed_sweep.hpp"

namespace dlpverify::compress {

double initial_packing(const Compression& c) {
  return packing_fraction(c.gas.spheres, c.gas.radius, c.gas.edge * c.gas.edge * c.gas.edge);
}

CompressionVerdict check_compression(const Compression& c, const std::vector<EnsembleRow>& rows,
                                     CompressionExpectation expectation, double tolerance) {
  CompressionVerdict verdict;
  switch (expectation) {
    case CompressionExpectation::seed_table: verdict.against = "Harrison's table 1"; break;
    case CompressionExpectation::adiabat: verdict.against = "adiabat"; break;
    case CompressionExpectation::carnahan_starling: verdict.against = "carnahan-starling"; break;
    case CompressionExpectation::law: verdict.against = "law"; break;
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const EnsembleRow& r = rows[i];
    double expected = ideal_adiabat(r.volume_ratio);
    if (expectation == CompressionExpectation::seed_table) expected = kSeedTable[i].simulated;
    if (expectation == CompressionExpectation::carnahan_starling)
      expected = carnahan_starling_adiabat(initial_packing(c), r.volume_ratio);
    if (expectation == CompressionExpectation::law) expected = law_for(c, r);
    const bool transitional =
        expectation == CompressionExpectation::law && classify(r.collisions_per_sphere_moving) == Regime::transitional;
    const double deviation = r.mean / expected - 1.0;
    if (std::fabs(deviation) <= tolerance && !transitional) continue;
    verdict.passed = false;
    verdict.misses.push_back({r.volume_ratio, r.mean, expected, deviation, transitional});
  }
  return verdict;
}

}  // namespace dlpverify::compress
