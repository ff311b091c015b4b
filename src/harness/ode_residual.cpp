#include "harness/ode_residual.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "problems/dlp/rates.hpp"

namespace dlpverify::exact {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Weights of the 8th-order central first difference, D_h y = Σ_k c_k [y(τ + k h) − y(τ − k h)] / h.
constexpr std::array<double, 4> kCentral8{4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0};

// Step / time scale. Write u = h / T. If the nearest singularity of the solution in the complex τ
// plane is a distance T away (drag: s = s0 / (1 + K s0 τ) has its pole at 1/(K s) before τ), then
// y⁽⁹⁾ ≈ 8! y′ / T⁸ and the truncation error of D_h, (h⁸/630) y⁽⁹⁾, is 64 u⁸ relative to y′.
// Rounding each y(τ ± k h) at ε‖y‖ adds 2 Σ|c_k| ε ‖y‖ / h ≈ 2.08 ε T / h = 2.08 ε / u relative
// (taking ‖y‖/‖y′‖ ≈ T). The sum 64 u⁸ + 2.08 ε / u is smallest at u⁹ = 2.08 ε / 512, u ≈ 0.0099:
// h = 0.01 T gives a truncation of ~6e-15 and a round-off of ~5e-14.
constexpr double kStepPerTimeScale = 0.01;
// For τ > 0 the stencil is kept inside [τ/2, 3τ/2] — never reaching back to the launch, where a
// closed form may change branch (a particle launched at rest under gravity is at the apex of
// SPEC §4.4 at τ = 0) — as long as that costs at most 10× the optimal round-off (h ≥ T / 1000,
// ~5e-13 relative). For smaller τ, or τ ≤ 0, the stencil is centred on τ and the closed form must
// continue smoothly through τ = 0 (true of SPEC §4.1–4.3, 4.5, 4.6).
constexpr double kSmallestStepPerTimeScale = 1e-3;

double norm3(const ParticleState& y, int first) {
  return std::sqrt(y[first] * y[first] + y[first + 1] * y[first + 1] + y[first + 2] * y[first + 2]);
}

// max(a, b) that propagates NaN.
double worst(double a, double b) { return std::isnan(a) || std::isnan(b) ? kNaN : std::max(a, b); }

// ‖D − f‖ / max(‖f‖, ‖y‖ / T, DBL_MIN) over the fields [first, first + count).
double group_residual(const ParticleState& difference, const ParticleState& rate, const ParticleState& y, int first,
                      int count, double scale) {
  double mismatch = 0.0, rate_size = 0.0, state_size = 0.0;
  for (int f = first; f < first + count; ++f) {
    mismatch += (difference[f] - rate[f]) * (difference[f] - rate[f]);
    rate_size += rate[f] * rate[f];
    state_size += y[f] * y[f];
  }
  const double denominator =
      std::max({std::sqrt(rate_size), std::sqrt(state_size) / scale, std::numeric_limits<double>::min()});
  return std::sqrt(mismatch) / denominator;
}
// No term limits the smoothness: the closed form is a polynomial of degree ≤ 2 in τ (vacuum,
// gravity), which D_h differentiates exactly, so only round-off matters, and it grows with the
// largest ‖y‖ on the stencil: ‖x(τ ± 4h)‖ ≤ ‖x‖ + 4h‖v‖ + 8h²‖a‖. The scale is the time to travel
// the particle's own distance from the origin, ‖x‖/‖v‖ or √(2‖x‖/‖a‖), whichever is shorter, so the
// stencil does not reach positions much larger than ‖x‖ (a particle released at rest 0.6 mm from
// the origin, 0.1 µs later, would otherwise get ‖x‖/‖v‖ = 600 s and a stencil reaching 30 m).
// With x = 0: |τ|, or 1 s at τ = 0 (then any step is exact).
double kinematic_time_scale(const ParticleState& y, const ParticleState& rate, double tau) {
  const double distance = norm3(y, X), speed = norm3(y, VX), acceleration = norm3(rate, VX);
  double scale = kInfinity;
  if (distance > 0.0 && speed > 0.0) scale = std::min(scale, distance / speed);
  if (distance > 0.0 && acceleration > 0.0) scale = std::min(scale, std::sqrt(2.0 * distance / acceleration));
  if (std::isfinite(scale) && scale > 0.0) return scale;
  return tau != 0.0 ? std::abs(tau) : 1.0;
}
}  // namespace

double time_scale(const Physics& physics, const ParticleState& y) {
  const Terms& terms = physics.terms;
  const Parameters& p = physics.parameters;
  const double diameter =
      terms.burning ? std::cbrt(6.0 * y[MASS] / (std::numbers::pi * p.rho_particle)) : p.diameter;
  double scale = kInfinity;

  if (terms.drag) {
    Physics drag_only = physics;  // burning stays on: it sets the diameter the drag sees
    drag_only.terms.gravity = drag_only.terms.heat = false;
    ParticleState rate;
    const ParticleRates drag_rates(drag_only);
    drag_rates(0.0, y, rate);
    const double speed = norm3(y, VX);
    const double deceleration = norm3(rate, VX);
    if (speed > 0.0 && deceleration > 0.0) scale = std::min(scale, speed / deceleration);
    if (terms.gravity && p.gravity > 0.0) {
      const double K = speed > 0.0 && deceleration > 0.0 ? deceleration / (speed * speed)
                                                         : 3.0 * p.rho_gas * p.cd / (4.0 * p.rho_particle * diameter);
      scale = std::min(scale, 1.0 / std::sqrt(p.gravity * K));
    }
  }
  if (terms.heat && y[MASS] > 0.0) {
    // dT/dt = λ (T_a − T) is linear in T: λ is the rate at T = T_a − 1 K.
    ParticleState probe = y, rate;
    probe[TEMPERATURE] = p.t_gas - 1.0;
    const ParticleRates rates(physics);
    rates(0.0, probe, rate);
    const double lambda = std::abs(rate[TEMPERATURE]);
    if (lambda > 0.0) scale = std::min(scale, 1.0 / lambda);
  }
  if (terms.burning && y[MASS] > 0.0) {
    ParticleState rate;
    const ParticleRates rates(physics);
    rates(0.0, y, rate);
    if (rate[MASS] != 0.0) scale = std::min(scale, y[MASS] / std::abs(rate[MASS]));
  }
  return scale;
}

OdeResidual ode_residual(ParticleSolution solution, const Physics& physics, const ParticleState& y0, double tau) {
  const ParticleState y = solution(physics, y0, tau);

  // The gas is steady, so the rates do not depend on t; τ is passed for the record.
  ParticleState rate;
  const ParticleRates rates(physics);
  rates(tau, y, rate);

  double scale = time_scale(physics, y);
  if (!std::isfinite(scale)) scale = kinematic_time_scale(y, rate, tau);
  double h = kStepPerTimeScale * scale;
  if (tau > 0.0) h = std::min(h, std::max(tau / 8.0, kSmallestStepPerTimeScale * scale));
  // Make τ + h exact, so the stencil's offsets are (very nearly) the multiples of h they claim to be.
  const double representable = (tau + h) - tau;
  if (representable > 0.0) h = representable;

  ParticleState difference{};
  for (int k = static_cast<int>(kCentral8.size()); k >= 1; --k) {  // smallest weights first
    const ParticleState ahead = solution(physics, y0, tau + k * h);
    const ParticleState behind = solution(physics, y0, tau - k * h);
    for (int f = 0; f < kFields; ++f) difference[f] += kCentral8[k - 1] * (ahead[f] - behind[f]);
  }
  for (double& d : difference) d /= h;

  OdeResidual r;
  r.position = group_residual(difference, rate, y, X, 3, scale);
  r.velocity = group_residual(difference, rate, y, VX, 3, scale);
  r.temperature = group_residual(difference, rate, y, TEMPERATURE, 1, scale);
  r.mass = group_residual(difference, rate, y, MASS, 1, scale);
  r.step = h;
  r.time_scale = scale;
  return r;
}

OdeResidual ode_residual(ParticleSolution solution, const Physics& physics, const Cloud& initial, double tau) {
  // The worst of two residuals, group by group (NaN wins: it must fail).
  const auto absorb = [](OdeResidual& into, const OdeResidual& r) {
    into.position = worst(into.position, r.position);
    into.velocity = worst(into.velocity, r.velocity);
    into.temperature = worst(into.temperature, r.temperature);
    into.mass = worst(into.mass, r.mass);
    into.step = std::max(into.step, r.step);
    into.time_scale = std::min(into.time_scale, r.time_scale);
  };
  OdeResidual total;
  total.time_scale = kInfinity;
#pragma omp parallel
  {
    OdeResidual local;
    local.time_scale = kInfinity;
#pragma omp for schedule(static) nowait
    for (Eigen::Index p = 0; p < initial.size(); ++p) absorb(local, ode_residual(solution, physics, initial.particle(p), tau));
#pragma omp critical(dlpverify_ode_residual)
    absorb(total, local);
  }
  return total;
}

}  // namespace dlpverify::exact
