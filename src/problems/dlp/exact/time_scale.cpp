#include "problems/dlp/exact/time_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "problems/dlp/rates.hpp"

namespace dlpverify::dlp::exact {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();

double norm3(const ParticleState& y, int first) {
  return std::sqrt(y[first] * y[first] + y[first + 1] * y[first + 1] + y[first + 2] * y[first + 2]);
}

// No term limits the smoothness: the closed form is a polynomial of degree ≤ 2 in τ (vacuum,
// gravity), which D_h differentiates exactly, so only round-off matters, and it grows with the
// largest ‖y‖ on the stencil: ‖x(τ ± 4h)‖ ≤ ‖x‖ + 4h‖v‖ + 8h²‖a‖. The scale is the time to travel
// the particle's own distance from the origin, ‖x‖/‖v‖ or √(2‖x‖/‖a‖), whichever is shorter, so the
// stencil does not reach positions much larger than ‖x‖ (a particle released at rest 0.6 mm from
// the origin, 0.1 µs later, would otherwise get ‖x‖/‖v‖ = 600 s and a stencil reaching 30 m).
// With x = 0: |τ|, or 1 s at τ = 0 (then any step is exact).
double kinematic_time_scale(const ParticleState& y, const ParticleState& rate, double tau) {
  const double distance = norm3(y, X), speed = dlp::speed(y), acceleration = norm3(rate, VX);
  double scale = kInfinity;
  if (distance > 0.0 && speed > 0.0) scale = std::min(scale, distance / speed);
  if (distance > 0.0 && acceleration > 0.0) scale = std::min(scale, std::sqrt(2.0 * distance / acceleration));
  if (std::isfinite(scale) && scale > 0.0) return scale;
  return tau != 0.0 ? std::abs(tau) : 1.0;
}
}  // namespace

double time_scale(const Physics& physics, const ParticleState& y) {
  const Terms& terms = physics.terms;
  const Parameters& p = physics.parameters;
  const double diameter =
      terms.burning ? std::cbrt(6.0 * y[MASS] / (std::numbers::pi * p.rho_particle)) : p.diameter;
  double scale = kInfinity;

  if (terms.drag) {
    Physics drag_only = physics;  // burning stays on: it sets the diameter the drag sees
    drag_only.terms.gravity = drag_only.terms.heat = false;
    ParticleState rate;
    const ParticleRates drag_rates(drag_only);
    drag_rates(0.0, y, rate);
    const double speed = dlp::speed(y);
    const double deceleration = norm3(rate, VX);
    if (speed > 0.0 && deceleration > 0.0) scale = std::min(scale, speed / deceleration);
    if (terms.gravity && p.gravity > 0.0) {
      const double K = speed > 0.0 && deceleration > 0.0 ? deceleration / (speed * speed)
                                                         : p.drag_kappa() / diameter;
      scale = std::min(scale, 1.0 / std::sqrt(p.gravity * K));
    }
  }
  if (terms.heat && y[MASS] > 0.0) {
    // dT/dt = λ (T_a − T) is linear in T: λ is the rate at T = T_a − 1 K.
    ParticleState probe = y, rate;
    probe[TEMPERATURE] = p.t_gas - 1.0;
    const ParticleRates rates(physics);
    rates(0.0, probe, rate);
    const double lambda = std::abs(rate[TEMPERATURE]);
    if (lambda > 0.0) scale = std::min(scale, 1.0 / lambda);
  }
  if (terms.burning && y[MASS] > 0.0) {
    ParticleState rate;
    const ParticleRates rates(physics);
    rates(0.0, y, rate);
    if (rate[MASS] != 0.0) scale = std::min(scale, y[MASS] / std::abs(rate[MASS]));
  }
  return scale;
}

double particle_time_scale(const Physics& physics, const ParticleState& y, double tau) {
  const double scale = time_scale(physics, y);
  if (std::isfinite(scale)) return scale;
  ParticleState rate;
  const ParticleRates rates(physics);
  rates(tau, y, rate);
  return kinematic_time_scale(y, rate, tau);
}

}  // namespace dlpverify::dlp::exact
