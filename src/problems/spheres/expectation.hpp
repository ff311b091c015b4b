// The verdict of a compression table (docs/hard-spheres.md, `compress --expect`): every row's
// simulated T2/T1 within a relative tolerance of what it is expected to be.
#pragma once

#include <string>
#include <vector>

#include "problems/spheres/compression.hpp"

namespace dlpverify::compress {

// What each row is compared with: Harrison's published table 1 (its seven ratios, in order), the
// ideal adiabat (V1/V2)^(2/3), the Carnahan–Starling adiabat, or the law of the row's regime.
enum class CompressionExpectation { seed_table, adiabat, carnahan_starling, law };

// A row outside the tolerance (or, against the law, in the transitional regime where no law holds).
struct CompressionMiss {
  double volume_ratio = 0.0;
  double simulated = 0.0;
  double expected = 0.0;
  double deviation = 0.0;  // simulated / expected − 1
  bool transitional = false;
};

struct CompressionVerdict {
  bool passed = true;
  std::string against;  // what the rows were compared with, in the user's words
  std::vector<CompressionMiss> misses;
};

// The packing fraction of the compression's gas before the walls move.
double initial_packing(const Compression& c);

// Every row of `rows` (from run_ensemble over the compression `c`) against `expectation`.
CompressionVerdict check_compression(const Compression& c, const std::vector<EnsembleRow>& rows,
                                     CompressionExpectation expectation, double tolerance);

}  // namespace dlpverify::compress
