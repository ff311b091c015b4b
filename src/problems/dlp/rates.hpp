// The DLP right-hand side of docs/model.md §1 for one particle, in a quiescent gas (u = 0, so w = −v).
//
//   dx/dt = v
//   dv/dt = (3 ρ_a / (4 ρ_p d)) (C_D ‖w‖) w + g
//   dT/dt = Q / (m c_s),  Q = π d k_a Nu (T_a − T),  Nu = 2 + 0.6 Pr^(1/3) Re^(1/2)
//   dm/dt = −c_b d²,      d = (6 m / (π ρ_p))^(1/3)
//
// Constants are folded once at construction so the per-particle call is a handful of flops.
// It is inline and non-virtual: steppers call it inside their per-particle loops.
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

class ParticleRates {
 public:
  explicit ParticleRates(const Physics& physics) : terms_(physics.terms) {
    const Parameters& p = physics.parameters;
    constexpr double pi = std::numbers::pi;
    diameter0_ = p.diameter;
    diameter_from_mass_ = 6.0 / (pi * p.rho_particle);
    drag_over_d_ = p.drag_prefactor();
    cd_ = p.cd;
    // C_D(Re) ‖w‖ = 0.48 ‖w‖ + 28 (ρ_a d / μ_a)^−0.85 ‖w‖^0.15: finite (zero) at ‖w‖ = 0 (docs/model.md §1).
    law_coefficient_ = 28.0 * std::pow(p.rho_gas / p.mu_gas, -0.85);
    reynolds_per_speed_diameter_ = p.rho_gas / p.mu_gas;
    gravity_ = p.gravity;
    heat_factor_ = pi * p.k_gas() / p.cs_particle;  // Q / (m c_s) = heat_factor · d Nu (T_a − T) / m
    nusselt_coefficient_ = 0.6 * std::cbrt(p.prandtl);
    t_gas_ = p.t_gas;
    burn_rate_ = p.burn_rate;
  }

  const Terms& terms() const { return terms_; }

  // dy/dt for one particle. t is unused (the gas is steady) but kept: the stepper concept passes it.
  // In and Out index a particle's fields: a ParticleState, or a member of a structure-of-arrays
  // block (BlockMember above), so the block right-hand side runs the very same arithmetic.
  template <class In, class Out>
  inline void operator()(double /*t*/, const In& y, Out&& dydt) const {
    dydt[X] = y[VX];
    dydt[Y] = y[VY];
    dydt[Z] = y[VZ];
    dydt[VX] = 0.0;
    dydt[VY] = 0.0;
    dydt[VZ] = 0.0;
    dydt[TEMPERATURE] = 0.0;
    dydt[MASS] = 0.0;

    const double d = terms_.burning ? std::cbrt(diameter_from_mass_ * y[MASS]) : diameter0_;
    double slip = 0.0;  // ‖w‖ = ‖v‖
    if (terms_.drag || terms_.heat) slip = speed(y);

    if (terms_.drag) {
      const double cd_times_slip = terms_.drag_law == DragLaw::constant
                                       ? cd_ * slip
                                       : 0.48 * slip + law_coefficient_ * std::pow(d, -0.85) * std::pow(slip, 0.15);
      const double rate = -drag_over_d_ / d * cd_times_slip;  // w = −v
      dydt[VX] = rate * y[VX];
      dydt[VY] = rate * y[VY];
      dydt[VZ] = rate * y[VZ];
    }
    if (terms_.gravity) dydt[VZ] -= gravity_;
    if (terms_.heat) {
      const double reynolds = reynolds_per_speed_diameter_ * slip * d;
      const double nusselt = 2.0 + nusselt_coefficient_ * std::sqrt(reynolds);
      dydt[TEMPERATURE] = heat_factor_ * d * nusselt * (t_gas_ - y[TEMPERATURE]) / y[MASS];
    }
    if (terms_.burning) dydt[MASS] = -burn_rate_ * d * d;
  }

 private:
  Terms terms_;
  double diameter0_, diameter_from_mass_, drag_over_d_, cd_, law_coefficient_;
  double reynolds_per_speed_diameter_, gravity_, heat_factor_, nusselt_coefficient_, t_gas_, burn_rate_;
};

}  // namespace dlpverify
