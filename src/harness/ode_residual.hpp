// ODE residual of a closed form (SPEC §4, last paragraph: "its time derivative, by a high-order
// finite difference, must satisfy the ODE").
//
// For a per-particle closed form y(τ) = S(physics, y0, τ) and the model's right-hand side f:
//
//   D_h y(τ) = Σ_{k=1..4} c_k [y(τ + k h) − y(τ − k h)] / h,
//              c = (4/5, −1/5, 4/105, −1/280)                  (8th-order central difference)
//            = y'(τ) − (h⁸/630) y⁽⁹⁾(τ) + O(h¹⁰)
//
//   residual_g = ‖D_h y_g(τ) − f_g(t, y(τ))‖ / max(‖f_g(t, y(τ))‖, ‖y_g(τ)‖ / T, DBL_MIN)
//
// for each field group g (position x, velocity v, temperature T, mass m), ‖·‖ the Euclidean norm
// over the group's components. T is the problem's time scale (see time_scale below) and h = T/100,
// or down to T/1000 for small τ > 0 to keep the stencil after the launch (the truncation /
// round-off balance behind these numbers is worked out in ode_residual.cpp), so
// ‖y_g‖ / T is the rate at which the group would change on that scale: it keeps the residual
// relative when the group's own rate is zero or nearly so (a particle at rest, T = T_a), where
// dividing by ‖f_g‖ would turn the finite difference's round-off into an arbitrarily large number.
//
// A correct closed form gives a residual of ~1e-13 (truncation and round-off of D_h); a wrong
// one gives a residual of order one. The closed form must be smooth on the stencil [τ − 4h, τ + 4h]:
// no burn-out, no apex of SPEC §4.4 inside it (there −K ‖v‖ v makes the velocity only C²).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "problems/dlp/exact/cloud_solution.hpp"
#include "problems/dlp/cloud.hpp"
#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::exact {

struct OdeResidual {
  double position = 0.0;     // relative residual of dx/dt = v
  double velocity = 0.0;     // relative residual of the momentum equation
  double temperature = 0.0;  // relative residual of the energy equation
  double mass = 0.0;         // relative residual of the mass equation
  double step = 0.0;         // the finite-difference step h used [s] (largest over a cloud)
  double time_scale = 0.0;   // the problem's time scale T the step was chosen from [s] (smallest over a cloud)

  // The largest of the four residuals; NaN if any is NaN (a closed form that returned NaN fails).
  double max() const {
    double worst = position;
    for (double r : {velocity, temperature, mass})
      worst = std::isnan(worst) || std::isnan(r) ? std::numeric_limits<double>::quiet_NaN() : std::max(worst, r);
    return worst;
  }
};

// The problem's local time scale at state y (SPEC §1 terms that are on; +∞ when none limits it):
//   drag:             ‖v‖ / ‖a_drag‖                    (= 1 / (K s) for constant C_D)
//   drag + gravity:   τ_c = 1 / √(g K_eff)              (SPEC §4.4; K_eff = ‖a_drag‖ / s², or
//                                                        K = 3 ρ_a C_D / (4 ρ_p d) at rest)
//   heat:             1 / λ, dT/dt = λ (T_a − T)         (= ρ_p d² c_s / (6 k_a Nu))
//   burning:          m / |dm/dt|                       (= d / (3 β); burn-out is 3× further)
// Gravity alone (a polynomial in τ) and vacuum have no time scale of their own; ode_residual then
// uses a kinematic one, min(‖x‖/‖v‖, √(2‖x‖/‖a‖)), which only bounds the round-off.
double time_scale(const Physics& physics, const ParticleState& y);

// The relative residual of one particle's closed form at τ (see the banner for the formula).
OdeResidual ode_residual(ParticleSolution solution, const Physics& physics, const ParticleState& y0, double tau);

// The same for every particle of a cloud: each group's largest residual over the particles.
OdeResidual ode_residual(ParticleSolution solution, const Physics& physics, const Cloud& initial, double tau);

}  // namespace dlpverify::exact
