// The DLP right-hand side over a block of particles in SIMD lanes (docs/model.md §1): the same
// formulas as the scalar ParticleRates (rate_terms in rates.hpp), evaluated for a whole block.
//
// Per chunk of up to 64 particles, three passes over structure-of-arrays data:
//   1. speeds ‖v‖ (and the diameter's argument when burning) — a vectorised loop;
//   2. the diameter ∛(6m/(πρ_p)) and the C_D(Re) law's power Re^−0.85 — SLEEF's 1-ulp vector
//      routines (simd/vector_math.hpp), the one thing the compiler cannot vectorise;
//   3. every rate — a vectorised loop (`#pragma omp simd`, checked with -fopt-info-vec).
// The active terms are template parameters: each combination is its own branch-free kernel,
// chosen once when the rates are built.
#pragma once

#include "problems/dlp/rates.hpp"

namespace dlpverify::dlp {

class BlockRates {
 public:
  explicit BlockRates(const Physics& physics);
  // dy/dt of `count` particles: field f of particle i at y[f][i] (dydt alike); y and dydt must not overlap.
  void operator()(int count, const double* const* y, double* const* dydt) const { kernel_(c_, count, y, dydt); }

  const RateConstants& constants() const { return c_; }

  using Kernel = void (*)(const RateConstants&, int, const double* const*, double* const*);

 private:
  RateConstants c_;
  Kernel kernel_;
};

}  // namespace dlpverify::dlp
