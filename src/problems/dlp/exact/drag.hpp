// docs/model.md §4.3 — drag only, constant C_D, quiescent gas.
//
//   ODE:    dx/dt = v,  dv/dt = −K ‖v‖ v,   K = 3 ρ_a C_D / (4 ρ_p d0)
//   exact:  the direction î = v0 / s0 is fixed and, with s0 = ‖v0‖,
//           s(τ) = s0 / (1 + K s0 τ),   x(τ) = x0 + î ln(1 + K s0 τ) / K
//
// The seed's eq. 23 is dimensionally wrong (docs/model.md §9); this is the corrected form.
// log1p keeps ln(1 + K s0 τ) accurate for the slow particles near the cloud centre.
#pragma once

#include <cmath>
#include <limits>

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

// The state y0 with its position and velocity NaN: where no closed form applies, say so rather
// than answer wrongly.
inline ParticleState no_closed_form(const ParticleState& y0) {
  ParticleState y = y0;
  for (int f = X; f <= VZ; ++f) y[f] = std::numeric_limits<double>::quiet_NaN();
  return y;
}

inline ParticleState drag(const Physics& physics, const ParticleState& y0, double tau) {
  ParticleState y = y0;
  const double K = physics.parameters.drag_constant();
  const double s0 = speed(y0);
  if (s0 == 0.0) return y;  // at rest: stays at rest
  const double stretch = K * s0 * tau;          // K s0 τ
  const double speed_ratio = 1.0 / (1.0 + stretch);  // s / s0
  const double distance_per_speed = std::log1p(stretch) / (K * s0);  // ‖x − x0‖ / s0
  for (int i = 0; i < 3; ++i) {
    y[X + i] = y0[X + i] + y0[VX + i] * distance_per_speed;
    y[VX + i] = y0[VX + i] * speed_ratio;
  }
  return y;
}

}  // namespace dlpverify::dlp::exact
