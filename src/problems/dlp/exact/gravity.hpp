// docs/model.md §4.2 — gravity only, in vacuum.
//
//   ODE:    dx/dt = v,  dv/dt = g,   g = (0, 0, −‖g‖)
//   exact:  v(τ) = v0 + g τ,  x(τ) = x0 + v0 τ + ½ g τ²
//
// The seed's eq. 25 writes î·g t; the solution is v0 + g τ (docs/model.md §9).
#pragma once

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

inline ParticleState gravity(const Physics& physics, const ParticleState& y0, double tau) {
  ParticleState y = y0;
  for (int i = 0; i < 3; ++i) y[X + i] = y0[X + i] + y0[VX + i] * tau;
  const double g = physics.parameters.gravity;
  y[Z] -= 0.5 * g * tau * tau;
  y[VZ] -= g * tau;
  return y;
}

}  // namespace dlpverify::dlp::exact
