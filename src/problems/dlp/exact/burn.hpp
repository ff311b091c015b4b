// docs/model.md §4.6 — burning + drag (+ heat): constant C_D, the d-law of burning, quiescent gas.
//
//   ODE:    dx/dt = v,  dv/dt = −(κ/d) ‖v‖ v,        κ = 3 ρ_a C_D / (4 ρ_p)   (so K = κ/d)
//           dm/dt = −c_b d²,  d = (6 m / (π ρ_p))^(1/3)          ⇔  dd/dt = −β,  β = 2 c_b / (π ρ_p)
//           dT/dt = λ(t) (T_a − T),  λ = π d k_a Nu / (m c_s) = 6 k_a Nu / (ρ_p c_s d²),
//           Nu = 2 + 0.6 Pr^(1/3) √Re,  Re = ρ_a s d / μ_a,  s = ‖v‖       (only if terms.heat)
//   exact:  d(τ) = d0 − β τ, burn-out at τ_b = d0/β;  m(τ) = π ρ_p d³/6 = m0 (d/d0)³;
//           the direction î = v0/s0 is fixed and, with u = ln(d0/d(τ)), a = β/(κ s0):
//             s(τ) = 1 / (1/s0 + (κ/β) u)
//             x(τ) = x0 + î D(τ),  D(τ) = (d0/κ) [E1s(a) − (d(τ)/d0) E1s(a + u)],
//           E1s(x) = eˣ E1(x), the scaled exponential integral (GSL gsl_sf_expint_E1_scaled);
//           T(τ) = T_a + (T0 − T_a) exp(−Λ(τ)),  Λ(τ) = ∫₀^τ λ dt:
//             at rest (s0 = 0, Nu = 2): Λ = (12 k_a/(ρ_p c_s β)) (1/d(τ) − 1/d0) = 12 k_a τ / (ρ_p c_s d0 d(τ))
//               (the second form, used here, has no cancellation and no 1/β);
//             moving: Λ by adaptive quadrature (GSL QAG, 61-point Gauss–Kronrod, epsabs 0,
//               epsrel 1e-13), a semi-analytic baseline.
//   D(τ) follows from D = ∫ s dτ with dτ = (d0/β) e^(−u) du: (d0/κ) ∫₀^u e^(−u′)/(a + u′) du′.
//
// Inputs: d0 comes from the particle's own mass, d0 = (6 m0/(π ρ_p))^(1/3), as ParticleRates
// computes it; u = −log1p(−β τ/d0) keeps u accurate for small β τ.
// c_b = 0 falls back to docs/model.md §4.3 / §4.5 (exact::drag_heat — exact::drag with heat off): the form
// above cancels badly as β → 0. With burning switched off (physics.terms.burning false) likewise.
// s0 = 0: the particle stays where it is, at rest; only m and T change.
// physics.terms.heat off: T stays T0. Drag is assumed constant-C_D; with drag off (κ = 0) the
// particle coasts at s0 and Λ is integrated the same way.
//
// Burn-out: evaluating at τ ≥ τ_b (the particle's own d0/β) throws dlpverify::InputError naming
// τ_b. exact::evaluate runs this in an OpenMP loop, where an exception cannot propagate (it would
// call std::terminate): a caller must check the duration first with check_before_burn_out().
//
// GSL: QAG's workspace is allocated per call and freed by RAII, so concurrent calls (one per
// particle, OpenMP threads) share nothing. GSL's default error handler aborts the process; it is
// switched off once, process-wide, on the first call of burn()/burn_heat_exponent() (see burn.cpp),
// and every GSL return code here is checked instead: a failure gives NaN, never a silent number.
#pragma once

#include <cstddef>

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

// β = 2 c_b / (π ρ_p), the rate at which the diameter shrinks [m/s].
double burn_diameter_rate(const Parameters& parameters);

// τ_b = d0/β = π ρ_p d0 / (2 c_b) for d0 = parameters.diameter; +∞ when c_b = 0.
// docs/model.md §8 defaults: 42.4 ms.
double burn_out_time(const Parameters& parameters);

// Throws InputError("duration", τ, "at or past burn-out at tau_b = … s") when τ ≥ burn_out_time.
void check_before_burn_out(const Parameters& parameters, double tau);

// Λ(τ) and how it was obtained.
struct HeatExponent {
  double value = 0.0;          // Λ(τ)
  double error = 0.0;          // QAG's absolute error estimate (0 for the closed form)
  int status = 0;              // GSL status of QAG (0 = GSL_SUCCESS)
  std::size_t intervals = 0;   // subintervals QAG used; 0 when the closed form was used
};

// The relative accuracy QAG is asked for, and the worst it is accepted at when GSL reports that
// 1e-13 could not be reached (GSL_EROUND, GSL_EMAXITER …): its estimate is still the best available.
// Measured with docs/model.md §8 defaults (s0 from 1e-3 to 100 m/s, τ up to 0.0424 s, 11 µs before burn-out):
// QAG always returns GSL_SUCCESS at 1e-13 with at most 9 subintervals, its error estimate ≤ 9e-14
// relative; against a 113-bit (__float128) composite Gauss–Legendre reference the actual error is
// ≤ 2e-15 up to τ = 0.04 s (d = 0.057 d0) and ~3e-13 at τ = 0.0424 s (d = 2.7e-4 d0), where the
// rounding of d = d0 − β t in double (a cancellation, relative ε d0/d) is the floor, not QAG.
// So the fallback has not been needed.
inline constexpr double kHeatQuadratureTolerance = 1e-13;
inline constexpr double kHeatQuadratureAccepted = 1e-11;

// Λ(τ) for a burning particle starting at y0 (closed form at rest, QAG when it moves).
// Throws InputError at or past burn-out. Value NaN when QAG fails beyond kHeatQuadratureAccepted.
HeatExponent burn_heat_exponent(const Physics& physics, const ParticleState& y0, double tau);

// The closed form above (an exact::ParticleSolution).
ParticleState burn(const Physics& physics, const ParticleState& y0, double tau);

}  // namespace dlpverify::dlp::exact
