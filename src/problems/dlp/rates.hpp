// The DLP right-hand side of docs/model.md §1 for one particle, in a quiescent gas (u = 0, so w = −v).
//
//   dx/dt = v
//   dv/dt = (3 ρ_a / (4 ρ_p d)) (C_D ‖w‖) w + g
//   dT/dt = Q / (m c_s),  Q = π d k_a Nu (T_a − T),  Nu = 2 + 0.6 Pr^(1/3) Re^(1/2)
//   dm/dt = −c_b d²,      d = (6 m / (π ρ_p))^(1/3)
//
// Constants are folded once (RateConstants); the formulas live in rate_terms, shared by the scalar
// per-particle path here and the SIMD block path (block_rates.hpp).
#pragma once

#include <cmath>
#include <numbers>

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify {

// Member i of a structure-of-arrays block: field f at field[f][i].
template <class Pointer>
struct BlockMember {
  Pointer const* field;
  int i;
  auto& operator[](int f) const { return field[f][i]; }
};

// The model's constants, folded once so the per-particle formulas are a handful of flops.
struct RateConstants {
  explicit RateConstants(const Physics& physics) : terms(physics.terms) {
    const Parameters& p = physics.parameters;
    constexpr double pi = std::numbers::pi;
    diameter0 = p.diameter;
    diameter_from_mass = 6.0 / (pi * p.rho_particle);
    drag_over_d = p.drag_prefactor();
    cd = p.cd;
    // C_D(Re) ‖w‖ = 0.48 ‖w‖ + 28 (ρ_a d / μ_a)^−0.85 ‖w‖^0.15: finite (zero) at ‖w‖ = 0 (docs/model.md §1).
    law_coefficient = 28.0 * std::pow(p.rho_gas / p.mu_gas, -0.85);
    reynolds_per_speed_diameter = p.rho_gas / p.mu_gas;
    gravity = p.gravity;
    heat_factor = pi * p.k_gas() / p.cs_particle;  // Q / (m c_s) = heat_factor · d Nu (T_a − T) / m
    nusselt_coefficient = 0.6 * std::cbrt(p.prandtl);
    t_gas = p.t_gas;
    burn_rate = p.burn_rate;
  }
  Terms terms;
  double diameter0, diameter_from_mass, drag_over_d, cd, law_coefficient;
  double reynolds_per_speed_diameter, gravity, heat_factor, nusselt_coefficient, t_gas, burn_rate;
};

// The formulas of docs/model.md §1, once: the scalar path (ParticleRates) and the SIMD block path
// (block_rates.hpp) both call these, given what each computes its own way — the diameter
// d = ∛(diameter_from_mass · m) and the law's powers d^−0.85 and ‖w‖^0.15 (libm or SLEEF).
namespace rate_terms {
// dv/dt = rate · v (w = −v): −(3 ρ_a/(4 ρ_p d)) C_D ‖w‖, with C_D constant or the C_D(Re) law.
inline double drag_rate(const RateConstants& c, double d, double slip, double d_pow, double slip_pow) {
  const double cd_times_slip =
      c.terms.drag_law == DragLaw::constant ? c.cd * slip : 0.48 * slip + c.law_coefficient * d_pow * slip_pow;
  return -c.drag_over_d / d * cd_times_slip;
}
// dT/dt = π d k_a Nu (T_a − T)/(m c_s), Nu = 2 + 0.6 Pr^(1/3) Re^(1/2), Re = ρ_a ‖w‖ d/μ_a.
inline double heat_rate(const RateConstants& c, double d, double slip, double T, double m) {
  const double reynolds = c.reynolds_per_speed_diameter * slip * d;
  const double nusselt = 2.0 + c.nusselt_coefficient * std::sqrt(reynolds);
  return c.heat_factor * d * nusselt * (c.t_gas - T) / m;
}
// dm/dt = −c_b d².
inline double mass_rate(const RateConstants& c, double d) { return -c.burn_rate * d * d; }
}  // namespace rate_terms

// The right-hand side of one particle, with libm's pow and cbrt: the scalar path.
class ParticleRates {
 public:
  explicit ParticleRates(const Physics& physics) : c_(physics) {}

  const Terms& terms() const { return c_.terms; }
  const RateConstants& constants() const { return c_; }

  // dy/dt for one particle. t is unused (the gas is steady) but kept: the stepper concept passes it.
  // In and Out index a particle's fields: a ParticleState, or a member of a structure-of-arrays
  // block (BlockMember above).
  template <class In, class Out>
  inline void operator()(double /*t*/, const In& y, Out&& dydt) const {
    const Terms& terms = c_.terms;
    dydt[X] = y[VX];
    dydt[Y] = y[VY];
    dydt[Z] = y[VZ];
    dydt[VX] = 0.0;
    dydt[VY] = 0.0;
    dydt[VZ] = 0.0;
    dydt[TEMPERATURE] = 0.0;
    dydt[MASS] = 0.0;

    const double d = terms.burning ? std::cbrt(c_.diameter_from_mass * y[MASS]) : c_.diameter0;
    double slip = 0.0;  // ‖w‖ = ‖v‖
    if (terms.drag || terms.heat) slip = speed(y);

    if (terms.drag) {
      const bool law = terms.drag_law == DragLaw::reynolds;
      const double rate = rate_terms::drag_rate(c_, d, slip, law ? std::pow(d, -0.85) : 0.0, law ? std::pow(slip, 0.15) : 0.0);
      dydt[VX] = rate * y[VX];
      dydt[VY] = rate * y[VY];
      dydt[VZ] = rate * y[VZ];
    }
    if (terms.gravity) dydt[VZ] -= c_.gravity;
    if (terms.heat) dydt[TEMPERATURE] = rate_terms::heat_rate(c_, d, slip, y[TEMPERATURE], y[MASS]);
    if (terms.burning) dydt[MASS] = rate_terms::mass_rate(c_, d);
  }

 private:
  RateConstants c_;
};

}  // namespace dlpverify
