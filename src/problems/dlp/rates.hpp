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

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp {

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
    reynolds_per_speed_diameter = p.rho_gas / p.mu_gas;
    gravity = p.gravity;
    heat_factor = pi * p.k_gas() / p.cs_particle;  // Q / (m c_s) = heat_factor · d Nu (T_a − T) / m
    nusselt_coefficient = 0.6 * std::cbrt(p.prandtl);
    t_gas = p.t_gas;
    burn_rate = p.burn_rate;
  }
  Terms terms;
  double diameter0, diameter_from_mass, drag_over_d, cd;
  double reynolds_per_speed_diameter, gravity, heat_factor, nusselt_coefficient, t_gas, burn_rate;
};

// The formulas of docs/model.md §1, once: the scalar path (ParticleRates) and the SIMD block path
// (block_rates.hpp) both call these, given what each computes its own way — the diameter
// d = ∛(diameter_from_mass · m) and the law's power law_reynolds^−0.85 (libm or SLEEF).
namespace rate_terms {
// Re = ρ_a ‖w‖ d / μ_a.
// Each formula is a template of the arithmetic Real: double, or Extended for a study in extended
// precision (dlpverify/extended.hpp), whose cbrt, pow and sqrt are found by argument lookup.
template <class Real>
inline Real reynolds(const RateConstants& c, Real slip, Real d) { return c.reynolds_per_speed_diameter * slip * d; }
// What the law's power is taken of: Re, but at least the smallest normal double, so Re^−0.85 is
// finite and 28 Re^−0.85 ‖w‖ is exactly 0 at zero slip, its limit (docs/model.md §1). It differs
// from Re only below a slip of ~1e-303 m/s. NaN stays NaN. (Not a select on Re > 0 in drag_rate:
// GCC does not if-convert a possibly trapping floating-point comparison in the ivdep rate loop,
// which then stayed scalar; this max is taken in the omp simd pass that feeds SLEEF.)
template <class Real>
inline Real law_reynolds(const RateConstants& c, Real slip, Real d) {
  return std::max(reynolds(c, slip, d), Real(std::numeric_limits<double>::min()));
}
// dv/dt = rate · v (w = −v): −(3 ρ_a/(4 ρ_p d)) C_D ‖w‖, with C_D constant or (Law) the C_D(Re)
// law, C_D ‖w‖ = 0.48 ‖w‖ + 28 Re^−0.85 ‖w‖, given re_pow = law_reynolds^−0.85. The law is a
// template parameter, so a block kernel's loop has no branch on it.
template <bool Law, class Real>
inline Real drag_rate(const RateConstants& c, Real d, Real slip, Real re_pow) {
  const Real cd_times_slip = Law ? 0.48 * slip + 28.0 * re_pow * slip : c.cd * slip;
  return -c.drag_over_d / d * cd_times_slip;
}
// dT/dt = π d k_a Nu (T_a − T)/(m c_s), Nu = 2 + 0.6 Pr^(1/3) Re^(1/2).
template <class Real>
inline Real heat_rate(const RateConstants& c, Real d, Real reynolds, Real T, Real m) {
  using std::sqrt;
  const Real nusselt = 2.0 + c.nusselt_coefficient * sqrt(reynolds);
  return c.heat_factor * d * nusselt * (c.t_gas - T) / m;
}
// dm/dt = −c_b d².
template <class Real>
inline Real mass_rate(const RateConstants& c, Real d) { return -c.burn_rate * d * d; }
}  // namespace rate_terms

// dy/dt of one particle (fields y[0 … kFields), rates r alike), given what each caller computes
// its own way: the speed ‖v‖, the diameter d and the law's power Re^−0.85. The active
// terms are template parameters, so each combination is branch-free code that vectorises across
// particles: the block kernels (block_rates.cpp) and the fused Runge–Kutta lanes (fused_steps.cpp).
template <bool Drag, bool Law, bool Gravity, bool Heat, bool Burning>
inline void particle_rates(const RateConstants& c, const double* y, double speed, double d, double re_pow, double* r) {
  r[X] = y[VX];
  r[Y] = y[VY];
  r[Z] = y[VZ];
  const double reynolds = Heat ? rate_terms::reynolds(c, speed, d) : 0.0;
  const double rate = Drag ? rate_terms::drag_rate<Law>(c, d, speed, re_pow) : 0.0;
  r[VX] = Drag ? rate * y[VX] : 0.0;
  r[VY] = Drag ? rate * y[VY] : 0.0;
  r[VZ] = Drag ? rate * y[VZ] : 0.0;
  if (Gravity) r[VZ] -= c.gravity;
  r[TEMPERATURE] = Heat ? rate_terms::heat_rate(c, d, reynolds, y[TEMPERATURE], y[MASS]) : 0.0;
  r[MASS] = Burning ? rate_terms::mass_rate(c, d) : 0.0;
}

// The right-hand side of one particle, with libm's pow and cbrt (QD's in Extended): the scalar
// path, and the extended one.
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
    using Real = std::remove_cvref_t<decltype(y[0])>;
    using std::cbrt, std::pow;
    const Terms& terms = c_.terms;
    dydt[X] = y[VX];
    dydt[Y] = y[VY];
    dydt[Z] = y[VZ];
    dydt[VX] = 0.0;
    dydt[VY] = 0.0;
    dydt[VZ] = 0.0;
    dydt[TEMPERATURE] = 0.0;
    dydt[MASS] = 0.0;

    const Real d = terms.burning ? Real(cbrt(c_.diameter_from_mass * y[MASS])) : Real(c_.diameter0);
    Real slip = 0.0;  // ‖w‖ = ‖v‖
    if (terms.drag || terms.heat) slip = speed(y);
    const Real reynolds = rate_terms::reynolds(c_, slip, d);

    if (terms.drag) {
      const bool law = terms.drag_law == DragLaw::reynolds;
      const Real re_pow = law ? Real(pow(rate_terms::law_reynolds(c_, slip, d), Real(-0.85))) : Real(0.0);
      const Real rate = law ? rate_terms::drag_rate<true>(c_, d, slip, re_pow) : rate_terms::drag_rate<false>(c_, d, slip, Real(0.0));
      dydt[VX] = rate * y[VX];
      dydt[VY] = rate * y[VY];
      dydt[VZ] = rate * y[VZ];
    }
    if (terms.gravity) dydt[VZ] -= c_.gravity;
    if (terms.heat) dydt[TEMPERATURE] = rate_terms::heat_rate(c_, d, reynolds, y[TEMPERATURE], y[MASS]);
    if (terms.burning) dydt[MASS] = rate_terms::mass_rate(c_, d);
  }

 private:
  RateConstants c_;
};

}  // namespace dlpverify::dlp
