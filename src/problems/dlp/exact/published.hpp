// The seed's published (wrong) closed forms, as exact::ParticleSolutions, for an audit to show
// failing (docs/model.md §9). Source: Kuhl & Grote, the particle-cloud expansion paper (seed 004), eqs. 21–26. They are
// transcribed as printed, not fixed; every reading below is a choice where the printed formula is
// ambiguous, and it is said so.
//
// Seed eq. 23 ("Drag Solution", for eq. 22: dv/dt = −K v², K = (ρ_a/ρ_p) 3 C_D / (4 d_p)):
//     v_p(t) = −K v_p⁰ î_p / ((t0 − t) v_p⁰ + 1)
//   Reading: v_p⁰ multiplies the unit vector î_p, so it is the scalar initial speed s0 = ‖v0‖ and
//   î_p = v0/s0 the particle's ray (the seed's own notation: v = ξ u_s î, eq. 9); t − t0 = τ. So
//     v(τ) = −K s0 î / (1 − s0 τ)
//   (dimensionally wrong: K s0 is 1/s, and s0 τ is metres; it is not even v0 at τ = 0).
//   Position: the seed gives none; here it is the integral of that velocity from x(t0) = x0,
//     x(τ) = x0 + K î ln(1 − s0 τ),
//   so dx/dt = v holds exactly and only the momentum equation can fail. Both blow up at τ = 1/s0
//   (10 ms for the 100 m/s outermost particle) and are NaN past it — as printed.
//
// Seed eq. 26 ("Complete Solution", drag + gravity superposed):
//     v_p(t) = −K v_p⁰ î_p / (1 − (t − t0) v_p⁰) + î_p · g t
//   The first term is eq. 23 (the same reading). The second is eq. 25's gravity term î·g t, read
//   literally: î·g is a dot product, a scalar, which the seed adds to a vector; following the seed's
//   convention of writing a vector as a scalar times î (as in the first term), it is read as the
//   vector (î·g) t î — the projection of g t on the particle's ray. t is the absolute time
//   t = t0 + τ (the same t as in the drag term, which is written with t − t0). So
//     v(τ) = −K s0 î / (1 − s0 τ) + (î·g)(t0 + τ) î,             g = (0, 0, −g)
//     x(τ) = x0 + K î ln(1 − s0 τ) + (î·g)(t0 τ + τ²/2) î         (the integral of v, x(t0) = x0)
//   A ParticleSolution knows only τ, so seed_complete_eq26 takes t0 from the launch of docs/model.md §2,
//   where x0 = v0 t0: t0 = ‖x0‖/s0 (exact for every particle of the lattice cloud); for any other
//   initial state use seed_complete_eq26_at with the t0 you mean.
//   The gravity term is used whatever physics.terms.gravity says (it is the seed's formula).
//
// superposed_drag_gravity: eq. 26 with its two parts corrected (docs/model.md §4.3 and §4.2: drag + g τ,
// x from both) but still superposed — what remains wrong is the superposition itself, since the
// drag ODE is nonlinear (docs/model.md §9).
//
// The seed's forms need s0 > 0 (î is undefined at rest): for s0 = 0 they return NaN for position and
// velocity. superposed_drag_gravity is defined at rest (it is then gravity alone).
#pragma once

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

// Seed eq. 23 (velocity as printed, position its integral).
ParticleState seed_drag_eq23(const Physics& physics, const ParticleState& y0, double tau);

// Seed eq. 26 with t0 = ‖x0‖/s0 (the similarity launch of docs/model.md §2).
ParticleState seed_complete_eq26(const Physics& physics, const ParticleState& y0, double tau);

// Seed eq. 26 with an explicit t0 (the absolute time of the launch).
ParticleState seed_complete_eq26_at(const Physics& physics, const ParticleState& y0, double tau, double t0);

// docs/model.md §4.3 drag plus the docs/model.md §4.2 gravity increment, superposed: x = x_drag − ½ g τ² ẑ, v = v_drag − g τ ẑ.
ParticleState superposed_drag_gravity(const Physics& physics, const ParticleState& y0, double tau);

}  // namespace dlpverify::dlp::exact
