#include "problems/dlp/block_rates.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "dlpverify/fused_runge_kutta.hpp"  // DLPVERIFY_INDEPENDENT_MEMBERS
#include "simd/vector_math.hpp"

namespace dlpverify::dlp {

namespace {

constexpr int kChunk = 64;  // the pass buffers: 3 × 64 doubles on the stack, in L1

template <bool Drag, bool Law, bool Gravity, bool Heat, bool Burning>
void rates_kernel(const RateConstants& constants, int count, const double* const* y, double* const* dydt) {
  // A local copy: stores through dydt cannot alias it, so its values stay in registers and
  // expressions of them (3ρ_a/(4ρ_p d0)) leave the loop.
  const RateConstants c = constants;
  // Without burning the diameter is the constant d0, so the drag prefactor 3ρ_a/(4ρ_p d0) is a
  // loop constant (no division per particle); with it, d is a lane array.
  alignas(64) double d_lanes[kChunk], slip[kChunk], re_pow[kChunk];
  for (int first = 0; first < count; first += kChunk) {
    const int n = std::min(kChunk, count - first);
    // The chunk's field pointers, local, so no store in the loops below can move them.
    const double* chunk[kFields];
    for (int f = 0; f < kFields; ++f) chunk[f] = y[f] + first;

    // 1. speeds, by speed() as in the fused steps (both paths give the same bits), and the
    // diameter's argument. Not omp simd: GCC would make speed()'s view a per-lane array.
    DLPVERIFY_INDEPENDENT_MEMBERS
    for (int i = 0; i < n; ++i) {
      // The law reads the slip too; a law without drag is never picked, but its kernel is compiled.
      if constexpr (Drag || Law || Heat) slip[i] = speed(BlockMember<const double*>{chunk, i});
      if constexpr (Burning) d_lanes[i] = c.diameter_from_mass * chunk[MASS][i];
    }
    // 2. what only SLEEF vectorises: d = ∛(…), and the law's Re^−0.85
    if constexpr (Burning) simd::cbrt(d_lanes, d_lanes, n);
    if constexpr (Law) {
#pragma omp simd
      for (int i = 0; i < n; ++i) re_pow[i] = rate_terms::law_reynolds(c, slip[i], Burning ? d_lanes[i] : c.diameter0);
      simd::pow(re_pow, -0.85, re_pow, n);
    }
    // 3. the rates
    DLPVERIFY_INDEPENDENT_MEMBERS
    for (int i = 0; i < n; ++i) {
      double particle[kFields], rates[kFields];
#pragma GCC unroll 8
      for (int f = 0; f < kFields; ++f) particle[f] = chunk[f][i];
      particle_rates<Drag, Law, Gravity, Heat, Burning>(c, particle, (Drag || Heat) ? slip[i] : 0.0,
                                                          Burning ? d_lanes[i] : c.diameter0, Law ? re_pow[i] : 0.0,
                                                          rates);
#pragma GCC unroll 8
      for (int f = 0; f < kFields; ++f) dydt[f][first + i] = rates[f];
    }
  }
}

// Kernel number `bits`: drag 1, law 2, gravity 4, heat 8, burning 16.
template <int Bits>
constexpr BlockRates::Kernel kKernel =
    &rates_kernel<(Bits & 1) != 0, (Bits & 2) != 0, (Bits & 4) != 0, (Bits & 8) != 0, (Bits & 16) != 0>;

template <int... Bits>
BlockRates::Kernel pick(int bits, std::integer_sequence<int, Bits...>) {
  static constexpr BlockRates::Kernel table[] = {kKernel<Bits>...};
  return table[bits];
}

}  // namespace

BlockRates::BlockRates(const Physics& physics) : c_(physics) {
  const Terms& t = physics.terms;
  const bool law = t.drag && t.drag_law == DragLaw::reynolds;
  const int bits = (t.drag ? 1 : 0) | (law ? 2 : 0) | (t.gravity ? 4 : 0) | (t.heat ? 8 : 0) | (t.burning ? 16 : 0);
  kernel_ = pick(bits, std::make_integer_sequence<int, 32>{});
}

}  // namespace dlpverify::dlp
