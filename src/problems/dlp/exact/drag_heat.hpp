// docs/model.md §4.5 — drag + heat transfer: constant C_D, Nu(Re) law, no burning, quiescent gas.
//
//   ODE:    dx/dt = v,  dv/dt = −K ‖v‖ v,                       K = 3 ρ_a C_D / (4 ρ_p d)
//           dT/dt = λ(t) (T_a − T),  λ = π d k_a Nu / (m c_s),   Nu = 2 + 0.6 Pr^(1/3) √Re,
//           Re = ρ_a s d / μ_a,  s = ‖v‖,  k_a = μ_a c_p / Pr,  dm/dt = 0 (d = d0, m = m0)
//   exact:  x, v as docs/model.md §4.3 (exact::drag: s = s0 / (1 + K s0 τ)), and, T being linear,
//           T(τ) = T_a + (T0 − T_a) exp(−Λ(τ)),  Λ(τ) = ∫₀^τ λ dt
//                = (π k_a d / (m c_s)) · [ 2τ + 0.6 Pr^(1/3) (ρ_a d/μ_a)^(1/2) · I(τ) ],
//           I(τ) = ∫₀^τ √s dt = 2 (√(s0 (1 + K s0 τ)) − √s0) / (K s0)
//                = 2 τ √s0 / (√(1 + K s0 τ) + 1)        (the form used: no cancellation, finite at s0 = 0)
//
// With m = π ρ_p d³/6 the prefactor is docs/model.md's 6 k_a / (ρ_p d² c_s). It is written with the particle's
// own mass, as ParticleRates computes it (heat term π d k_a Nu (T_a − T)/(m c_s) with d = d0 when
// burning is off), so a particle whose m0 differs from π ρ_p d0³/6 still gets the solution of the
// ODE the integrators solve. At rest (s0 = 0) Nu = 2 and T relaxes with time constant
// ρ_p d² c_s / (12 k_a). The drag part is exact::drag itself, not a copy.
// physics.terms.heat off: T stays T0 (the result is exact::drag's). Assumes constant C_D.
#pragma once

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

// Λ(τ) above for a particle starting at y0 (its speed s0 = ‖v0‖ and mass m0 = y0[MASS]).
double drag_heat_exponent(const Physics& physics, const ParticleState& y0, double tau);

// The closed form above (an exact::ParticleSolution).
ParticleState drag_heat(const Physics& physics, const ParticleState& y0, double tau);

}  // namespace dlpverify::dlp::exact
