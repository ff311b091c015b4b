// A gas parcel's prescribed compression path (docs/model.md §7.1): smooth compression from J = 1
// to its deepest point J_min at half the period, and back to J = 1 at the full period,
//   J(τ) = 1 − (1 − J_min) sin²(π τ/P),   dJ/dτ = −(1 − J_min) (π/P) sin(2π τ/P),
// with τ the time since the start. Every derivative exists (the adiabat's closed form is smooth in
// τ), so a method's order shows on it, and J̇(0) = 0: the parcel starts at rest in its reference state.
#pragma once

#include <cmath>

#include <numbers>

namespace dlpverify::gas {

struct CompressionPath {
  double j_min = 0.5;    // the deepest compression, at τ = P/2
  double period = 1e-3;  // P [s]

  double J(double tau) const {
    const double s = std::sin(std::numbers::pi * tau / period);
    return 1.0 - (1.0 - j_min) * s * s;
  }
  double rate(double tau) const {  // dJ/dτ [1/s]
    return -(1.0 - j_min) * (std::numbers::pi / period) * std::sin(2.0 * std::numbers::pi * tau / period);
  }
  // The smallest J over [0, duration]: J falls on [0, P/2] and is periodic.
  double smallest_J(double duration) const { return duration >= 0.5 * period ? j_min : J(duration); }
  // The first time J reaches `level` (j_min ≤ level ≤ 1): sin²(π τ/P) = (1 − level)/(1 − j_min).
  double time_to_reach(double level) const {
    return period / std::numbers::pi * std::asin(std::sqrt((1.0 - level) / (1.0 - j_min)));
  }
};

}  // namespace dlpverify::gas
