// docs/model.md §4.4 — vertical drag + gravity, constant C_D, quiescent gas, v ∥ g (z up).
//
//   ODE:    dz/dt = w,  dw/dt = −K |w| w − g,     w = v_z,  g = (0, 0, −g),  K = 3 ρ_a C_D / (4 ρ_p d0)
//           (x, y and v_x = v_y = 0 do not change)
//   scales: terminal speed v_t = √(g/K), time scale τ_c = v_t / g = 1/√(g K), and K v_t τ_c = 1
//   exact (δ = σ = τ/τ_c):
//     rising (w0 > 0), φ0 = atan(w0/v_t), up to the apex τ_a = τ_c φ0:
//         w = v_t tan(φ0 − δ),        z = z0 + ln(cos(φ0 − δ) / cos φ0) / K
//       after it the particle falls from rest (ψ0 = 0 below) from z_a = z0 + ln(1/cos φ0)/K at τ_a
//     falling slower than v_t (0 ≤ −w0 < v_t), ψ0 = atanh(−w0/v_t):
//         w = −v_t tanh(ψ0 + σ),      z = z0 − ln(cosh(ψ0 + σ) / cosh ψ0) / K
//     falling faster than v_t (−w0 > v_t), ψ0 = atanh(v_t/(−w0)):
//         w = −v_t coth(ψ0 + σ),      z = z0 − ln(sinh(ψ0 + σ) / sinh ψ0) / K
//     terminal (−w0 = v_t):           w = −v_t,  z = z0 − v_t τ
//
// How it is evaluated (vertical_drag_gravity.cpp): by the addition theorems, with r = w0/v_t and
// c = −w0/v_t, never through atan/atanh/acoth of the initial state —
//     rising:   w = v_t (r − tan δ) / (1 + r tan δ),      z = z0 + ln(cos δ + r sin δ) / K
//     falling:  w = −v_t (c + tanh σ) / (1 + c tanh σ),   z = z0 − ln(cosh σ + c sinh σ) / K
// The falling form is the same expression for all three falling branches (tanh ψ0 = c when c < 1,
// coth ψ0 = c when c > 1, and c = 1 is the terminal solution), so nothing is lost near v_t, where
// atanh/acoth of a ratio close to 1 would amplify its rounding by 1/(1 − c²).
//
// Precondition: the motion is vertical, vertical_motion(y0) (v_x = v_y = 0). With any horizontal
// velocity the drag couples the components and there is no closed form (docs/model.md §4.4: use CVODE);
// the function then returns NaN for position and velocity rather than a wrong answer (it runs in
// exact::evaluate's OpenMP loop, where it cannot throw). It also assumes constant C_D.
// Degenerate parameters: g = 0 gives docs/model.md §4.3 (exact::drag), K = 0 gives §4.2 (exact::gravity).
// The apex is a point where the velocity is only C² (|w| w): exact::ode_residual must not straddle it.
#pragma once

#include <string_view>

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

// Terminal speed v_t = √(g/K) and the time scale τ_c = v_t / g = 1/√(g K) of docs/model.md §4.4.
double terminal_speed(const Parameters& parameters);
double drag_gravity_time(const Parameters& parameters);

// True when the particle moves along g only (v_x = v_y = 0): the precondition of vertical_drag_gravity.
inline bool vertical_motion(const ParticleState& y) { return y[VX] == 0.0 && y[VY] == 0.0; }

// The time of the apex, τ_a = τ_c atan(w0/v_t), for a rising particle (w0 > 0); 0 otherwise.
double apex_time(const Physics& physics, const ParticleState& y0);

// Which branch of docs/model.md §4.4 a particle takes over [0, τ].
enum class VerticalBranch {
  rising,               // w0 > 0 and τ ≤ τ_a: still rising (or just at the apex)
  rising_through_apex,  // w0 > 0 and τ > τ_a: rose, stopped, and is falling from rest
  falling_slower,       // 0 ≤ −w0 < v_t (a particle at rest included)
  falling_faster,       // −w0 > v_t: slows down towards v_t from above
  terminal,             // −w0 = v_t exactly (as computed by terminal_speed): stays at −v_t
};
inline constexpr int kVerticalBranches = 5;
VerticalBranch vertical_branch(const Physics& physics, const ParticleState& y0, double tau);
std::string_view to_string(VerticalBranch branch);  // "rising", "rising-through-apex", …

// The closed form above (an exact::ParticleSolution). Assumes vertical_motion(y0); T and m unchanged.
ParticleState vertical_drag_gravity(const Physics& physics, const ParticleState& y0, double tau);

}  // namespace dlpverify::dlp::exact
