/// @file
/// Explicit Runge–Kutta steps of a block of members with the right-hand side inlined into the stage
/// loops: one pass over the block per stage, the stage argument held in registers, no stage buffer.
///
/// runge_kutta.hpp's generic step calls Problem::rhs once per block and stage, and between the
/// calls it writes the stage argument y + Δt Σ_j a_ij k_j to a buffer and reads it back. When the
/// rates of one member are a small inline function (a LaneRates), this file forms the argument,
/// evaluates the rates and stores k_i in one loop over the block's members, which the compiler
/// vectorises across members. The last stage also adds Δt Σ_i b_i k_i to y in the same loop.
/// The arithmetic is the generic step's, in the same order (y + h_1 k_1 + h_2 k_2 …, the same
/// rate formulas), so both give the same bits; unit.fused_runge_kutta checks it.
///
/// A LaneRates type provides
/// @code{.unparsed}
///   static constexpr int kFields;                         F, the problem's field count
///   static constexpr std::array<bool, kFields> kActive;   false for an inert field (rate 0)
///   void operator()(double t, const double* y, double* dydt) const;   y, dydt: F values
/// @endcode
/// and its operator() must be inline code the compiler vectorises (+, ×, ÷, sqrt: no calls).
/// Written by hand: no library fuses a Runge–Kutta tableau with a user's rates across SIMD lanes.
#pragma once

#include <array>
#include <type_traits>
#include <utility>

#include "dlpverify/level_stop.hpp"

/// @def DLPVERIFY_INDEPENDENT_MEMBERS
/// Marks the member loops of a fused stage as free of loop-carried dependences: members are
/// independent, and the stores to y of one member never reach another's. Not `#pragma omp simd`:
/// GCC 12 turns the lane's local arrays inside an omp simd loop into per-lane arrays it then
/// cannot vectorise; after inlining they are registers.
#if defined(__clang__)
#define DLPVERIFY_INDEPENDENT_MEMBERS _Pragma("clang loop vectorize(assume_safety)")
#else
#define DLPVERIFY_INDEPENDENT_MEMBERS _Pragma("GCC ivdep")
#endif

namespace dlpverify {

/// Calls body(std::integral_constant<int, I>{}) for I = 0 … N−1: loops over fields and stages
/// unrolled in the source, so the stage loop over members holds no inner loop and no branch, and
/// the compiler vectorises it (GCC does not unroll a `#pragma GCC unroll` loop before vectorising).
template <int N, class Body>
inline void for_each_index(Body&& body) {
  [&]<int... I>(std::integer_sequence<int, I...>) {
    (body(std::integral_constant<int, I>{}), ...);
  }(std::make_integer_sequence<int, N>{});
}

/// One stage of one step: k_Stage = f(t, y + Δt Σ_j a_Stage,j k_j) for members [0, count); in the
/// last stage also y += Δt Σ_i b_i k_i. Count is a compile-time constant for a full block (no
/// remainder loop), else 0 and `count` is used.
template <const auto& Tableau, int Stage, class Lane, int Block, int Count>
inline void fused_stage(const Lane& lane_given, double* const* y, int count, double t, double dt,
                        double (&k)[Tableau.b.size()][Lane::kFields][Block]) {
  // A copy whose address does not escape: the stores to y cannot alias it, so the lane's
  // constants and the branches on them leave the loop.
  const Lane lane = lane_given;
  constexpr int F = Lane::kFields;
  constexpr int stages = static_cast<int>(Tableau.b.size());
  const int n = Count > 0 ? Count : count;
  double* yf[F];
  for (int f = 0; f < F; ++f) yf[f] = y[f];
  const double t_stage = t + Tableau.c[Stage] * dt;
  DLPVERIFY_INDEPENDENT_MEMBERS
  for (int m = 0; m < n; ++m) {
    double s[F], r[F];
    // The stage argument: y + h_1 k_1 + h_2 k_2 …, zero coefficients skipped at compile time.
    for_each_index<F>([&](auto f) {
      s[f] = yf[f][m];
      if constexpr (Lane::kActive[f])
        for_each_index<Stage>([&](auto j) {
          if constexpr (Tableau.a[Stage][j] != 0.0) s[f] += (dt * Tableau.a[Stage][j]) * k[j][f][m];
        });
    });
    lane(t_stage, s, r);
    for_each_index<F>([&](auto f) {
      if constexpr (!Lane::kActive[f]) return;
      if constexpr (Stage + 1 < stages) {
        k[Stage][f][m] = r[f];
      } else {  // the last stage: y + Δt b_1 k_1 + Δt b_2 k_2 …, in the generic step's order
        double yv = yf[f][m];
        for_each_index<stages - 1>([&](auto i) {
          if constexpr (Tableau.b[i] != 0.0) yv += (dt * Tableau.b[i]) * k[i][f][m];
        });
        if constexpr (Tableau.b[stages - 1] != 0.0) yv += (dt * Tableau.b[stages - 1]) * r[f];
        yf[f][m] = yv;
      }
    });
  }
}

/// One whole step: fused_stage for each stage of the tableau in turn (Stage = 0 … s−1).
template <const auto& Tableau, class Lane, int Block, int Count, int... Stage>
inline void fused_step(const Lane& lane, double* const* y, int count, double t, double dt,
                       double (&k)[Tableau.b.size()][Lane::kFields][Block], std::integer_sequence<int, Stage...>) {
  (fused_stage<Tableau, Stage, Lane, Block, Count>(lane, y, count, t, dt, k), ...);
}

/// `steps` steps of the tableau from t0 by dt for the `count` ≤ Block members at y[f][0 … count).
template <const auto& Tableau, class Lane, int Block>
void fused_runge_kutta_steps(const Lane& lane, double* const* y, int count, double t0, double dt, long steps) {
  constexpr int stages = static_cast<int>(Tableau.b.size());
  alignas(64) double k[stages][Lane::kFields][Block];
  const auto sequence = std::make_integer_sequence<int, stages>{};
  if (count == Block)
    for (long n = 0; n < steps; ++n) {
      abandon_level_if_stop_requested();
      fused_step<Tableau, Lane, Block, Block>(lane, y, count, t0 + static_cast<double>(n) * dt, dt, k, sequence);
    }
  else
    for (long n = 0; n < steps; ++n) {
      abandon_level_if_stop_requested();
      fused_step<Tableau, Lane, Block, 0>(lane, y, count, t0 + static_cast<double>(n) * dt, dt, k, sequence);
    }
}

}  // namespace dlpverify
