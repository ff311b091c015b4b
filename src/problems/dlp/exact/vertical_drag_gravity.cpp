#include "problems/dlp/exact/vertical_drag_gravity.hpp"

#include <cmath>
#include <limits>

#include "problems/dlp/exact/drag.hpp"
#include "problems/dlp/exact/gravity.hpp"

namespace dlpverify::dlp::exact {

namespace {

// ln(cos(φ0 − δ) / cos φ0) = ln(cos δ + r sin δ), r = tan φ0, for the rising branch (0 ≤ δ ≤ φ0).
// Written as log1p(r sin δ − 2 sin²(δ/2)) (cos δ = 1 − 2 sin²(δ/2)): no ln of a ratio of cosines,
// so no cancellation as δ → 0, where ln cos(φ0 − δ) − ln cos φ0 would subtract two nearly equal
// logarithms, and no ln(cos θ) of a cosine near 1 at the apex. The subtracted term is at most half
// the first one on [0, φ0] (tan(δ/2)/r ≤ tan(φ0/2)/tan φ0 ≤ ½), so the argument loses nothing.
double rising_log(double r, double delta) {
  const double half = std::sin(0.5 * delta);
  return std::log1p(r * std::sin(delta) - 2.0 * half * half);
}

// The apex height above z0 times K: ln(1/cos φ0) = ½ ln(1 + r²) (exact from cos(atan r) = 1/√(1 + r²)).
double apex_log(double r) { return r < 1e100 ? 0.5 * std::log1p(r * r) : std::log(r); }

// ln(cosh σ + c sinh σ), the falling branches' ln(cosh(ψ0 + σ)/cosh ψ0) (c = tanh ψ0 < 1) or
// ln(sinh(ψ0 + σ)/sinh ψ0) (c = coth ψ0 > 1). For |σ| ≤ 1, log1p(2 sinh²(σ/2) + c sinh σ)
// (cosh σ = 1 + 2 sinh²(σ/2)): every term is small and, for σ ≥ 0, non-negative, so it is accurate
// as σ → 0. For σ > 1, cosh and sinh would overflow past σ ≈ 710, and ln(sinh) of a large argument
// must not be taken literally: factor out e^σ (1 + c)/2,
//   ln(cosh σ + c sinh σ) = σ + ln((1 + c)/2) + log1p(e^(−2σ) (1 − c)/(1 + c)),
// whose terms cannot cancel badly there (the sum is ≥ 1 − ln 2 − 0.15 > 0.15).
double falling_log(double c, double sigma) {
  if (std::abs(sigma) <= 1.0) {
    const double half = std::sinh(0.5 * sigma);
    return std::log1p(2.0 * half * half + c * std::sinh(sigma));
  }
  if (sigma > 1.0) return sigma + std::log(0.5 * (1.0 + c)) + std::log1p(std::exp(-2.0 * sigma) * (1.0 - c) / (1.0 + c));
  return std::log(std::cosh(sigma) + c * std::sinh(sigma));  // σ < −1: before launch, only if asked for
}
}  // namespace

double terminal_speed(const Parameters& parameters) {
  return std::sqrt(parameters.gravity / parameters.drag_constant());
}

double drag_gravity_time(const Parameters& parameters) {
  return 1.0 / std::sqrt(parameters.gravity * parameters.drag_constant());
}

double apex_time(const Physics& physics, const ParticleState& y0) {
  if (!(y0[VZ] > 0.0)) return 0.0;
  const Parameters& p = physics.parameters;
  if (p.gravity == 0.0) return std::numeric_limits<double>::infinity();  // never stops rising
  if (p.drag_constant() == 0.0) return y0[VZ] / p.gravity;               // gravity alone
  return drag_gravity_time(p) * std::atan(y0[VZ] / terminal_speed(p));
}

VerticalBranch vertical_branch(const Physics& physics, const ParticleState& y0, double tau) {
  const double w0 = y0[VZ];
  if (w0 > 0.0) return tau > apex_time(physics, y0) ? VerticalBranch::rising_through_apex : VerticalBranch::rising;
  const double vt = terminal_speed(physics.parameters);
  if (-w0 == vt) return VerticalBranch::terminal;
  return -w0 < vt ? VerticalBranch::falling_slower : VerticalBranch::falling_faster;
}

std::string_view to_string(VerticalBranch branch) {
  switch (branch) {
    case VerticalBranch::rising: return "rising";
    case VerticalBranch::rising_through_apex: return "rising-through-apex";
    case VerticalBranch::falling_slower: return "falling-slower";
    case VerticalBranch::falling_faster: return "falling-faster";
    case VerticalBranch::terminal: return "terminal";
  }
  return "unknown";
}

ParticleState vertical_drag_gravity(const Physics& physics, const ParticleState& y0, double tau) {
  if (!vertical_motion(y0)) return no_closed_form(y0);
  const Parameters& p = physics.parameters;
  const double K = p.drag_constant(), g = p.gravity;
  if (g == 0.0) return drag(physics, y0, tau);
  if (K == 0.0) return gravity(physics, y0, tau);

  const double vt = std::sqrt(g / K);  // v_t
  const double tc = vt / g;            // τ_c
  const double w0 = y0[VZ];
  const double delta = tau / tc;  // δ = σ = τ / τ_c
  double w, rise;                 // w(τ) and K (z(τ) − z0)

  if (w0 > 0.0) {
    const double r = w0 / vt;  // tan φ0
    const double phi0 = std::atan(r);
    if (delta <= phi0) {  // rising: tan(φ0 − δ) = (r − tan δ)/(1 + r tan δ), accurate as δ → 0
      const double t = std::tan(delta);
      w = vt * (r - t) / (1.0 + r * t);
      rise = rising_log(r, delta);
    } else {  // past the apex τ_a = τ_c φ0: falling from rest (c = 0) from z_a
      const double sigma = delta - phi0;
      w = -vt * std::tanh(sigma);
      rise = apex_log(r) - falling_log(0.0, sigma);
    }
  } else {
    const double c = -w0 / vt;  // tanh ψ0 (slower), coth ψ0 (faster), 1 (terminal)
    if (c == 1.0) {
      w = -vt;
      rise = -delta;  // K v_t τ = τ / τ_c
    } else {  // tanh(ψ0 + σ) = (c + tanh σ)/(1 + c tanh σ); coth(ψ0 + σ) is the same expression in c
      const double t = std::tanh(delta);
      w = -vt * (c + t) / (1.0 + c * t);
      rise = -falling_log(c, delta);
    }
  }
  ParticleState y = y0;
  y[Z] = y0[Z] + rise / K;
  y[VZ] = w;
  return y;
}

}  // namespace dlpverify::dlp::exact
