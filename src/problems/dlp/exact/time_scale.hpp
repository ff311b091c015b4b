// The DLP particle's local time scale (docs/model.md §4, last paragraph): the ODE residual of a
// closed form takes its finite-difference step from it.
//
//   drag:             ‖v‖ / ‖a_drag‖                    (= 1 / (K s) for constant C_D)
//   drag + gravity:   τ_c = 1 / √(g K_eff)              (§4.4; K_eff = ‖a_drag‖ / s², or
//                                                        K = 3 ρ_a C_D / (4 ρ_p d) at rest)
//   heat:             1 / λ, dT/dt = λ (T_a − T)         (= ρ_p d² c_s / (6 k_a Nu))
//   burning:          m / |dm/dt|                       (= d / (3 β); burn-out is 3× further)
// Gravity alone (a polynomial in τ) and vacuum have no time scale of their own: then a kinematic
// one, min(‖x‖/‖v‖, √(2‖x‖/‖a‖)), which only bounds the round-off (see time_scale.cpp).
#pragma once

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

// The physical time scale of the active terms at state y; +∞ when none limits it.
double time_scale(const Physics& physics, const ParticleState& y);

// time_scale, or where it is +∞ the kinematic scale (|τ|, or 1 s at τ = 0 for a particle at
// the origin).
double particle_time_scale(const Physics& physics, const ParticleState& y, double tau);

}  // namespace dlpverify::dlp::exact
