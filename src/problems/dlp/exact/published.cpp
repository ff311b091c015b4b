#include "problems/dlp/exact/published.hpp"

#include <cmath>

#include "problems/dlp/exact/drag.hpp"

namespace dlpverify::dlp::exact {

ParticleState seed_drag_eq23(const Physics& physics, const ParticleState& y0, double tau) {
  const double s0 = speed(y0);
  if (s0 == 0.0) return no_closed_form(y0);
  const double K = physics.parameters.drag_constant();
  const double v_along = -K * s0 / (1.0 - s0 * tau);        // −K v⁰ / ((t0 − t) v⁰ + 1)
  const double x_along = K * std::log(1.0 - s0 * tau);      // ∫₀^τ of it
  ParticleState y = y0;
  for (int i = 0; i < 3; ++i) {
    const double direction = y0[VX + i] / s0;  // î
    y[VX + i] = v_along * direction;
    y[X + i] = y0[X + i] + x_along * direction;
  }
  return y;
}

ParticleState seed_complete_eq26_at(const Physics& physics, const ParticleState& y0, double tau, double t0) {
  const double s0 = speed(y0);
  if (s0 == 0.0) return no_closed_form(y0);
  ParticleState y = seed_drag_eq23(physics, y0, tau);
  const double gravity_along = -physics.parameters.gravity * y0[VZ] / s0;  // î·g, g = (0, 0, −g)
  const double v_along = gravity_along * (t0 + tau);                      // (î·g) t
  const double x_along = gravity_along * (t0 * tau + 0.5 * tau * tau);    // ∫₀^τ (î·g)(t0 + τ′) dτ′
  for (int i = 0; i < 3; ++i) {
    const double direction = y0[VX + i] / s0;
    y[VX + i] += v_along * direction;
    y[X + i] += x_along * direction;
  }
  return y;
}

ParticleState seed_complete_eq26(const Physics& physics, const ParticleState& y0, double tau) {
  const double s0 = speed(y0);
  if (s0 == 0.0) return no_closed_form(y0);
  const double t0 = std::sqrt(y0[X] * y0[X] + y0[Y] * y0[Y] + y0[Z] * y0[Z]) / s0;  // x0 = v0 t0 (docs/model.md §2)
  return seed_complete_eq26_at(physics, y0, tau, t0);
}

ParticleState superposed_drag_gravity(const Physics& physics, const ParticleState& y0, double tau) {
  ParticleState y = drag(physics, y0, tau);
  const double g = physics.parameters.gravity;
  y[Z] -= 0.5 * g * tau * tau;
  y[VZ] -= g * tau;
  return y;
}

}  // namespace dlpverify::dlp::exact
