#include "problems/dlp/exact/drag_heat.hpp"

#include <cmath>
#include <numbers>

#include "problems/dlp/exact/drag.hpp"

namespace dlpverify::dlp::exact {

double drag_heat_exponent(const Physics& physics, const ParticleState& y0, double tau) {
  const Parameters& p = physics.parameters;
  const double d = p.diameter;
  const double K = p.drag_constant();
  const double s0 = speed(y0);
  // I(τ) = ∫₀^τ √s dt in its stable form 2 τ √s0 / (√(1 + K s0 τ) + 1) (docs/model.md §4.5).
  const double integral = 2.0 * tau * std::sqrt(s0) / (std::sqrt(1.0 + K * s0 * tau) + 1.0);
  const double prefactor = std::numbers::pi * p.k_gas() * d / (y0[MASS] * p.cs_particle);
  const double convective = 0.6 * std::cbrt(p.prandtl) * std::sqrt(p.rho_gas * d / p.mu_gas);
  return prefactor * (2.0 * tau + convective * integral);
}

ParticleState drag_heat(const Physics& physics, const ParticleState& y0, double tau) {
  ParticleState y = drag(physics, y0, tau);
  if (!physics.terms.heat) return y;
  const double t_gas = physics.parameters.t_gas;
  y[TEMPERATURE] = t_gas + (y0[TEMPERATURE] - t_gas) * std::exp(-drag_heat_exponent(physics, y0, tau));
  return y;
}

}  // namespace dlpverify::dlp::exact
