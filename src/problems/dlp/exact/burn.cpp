#include "problems/dlp/exact/burn.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_expint.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <string>

#include "problems/dlp/exact/drag_heat.hpp"
#include "dlpverify/errors.hpp"
#include "io/gsl_errors.hpp"

namespace dlpverify::dlp::exact {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = std::numbers::pi;
// QAG's subinterval budget. The integrand is smooth on [0, τ] for τ < τ_b; GSL needs only a few
// subintervals of the 61-point rule even close to burn-out, where λ ∝ 1/d² steepens.
constexpr std::size_t kQuadratureIntervals = 200;

// GSL's default handler would abort() on any QAG error (e.g. GSL_EROUND when it judges 1e-13
// out of reach); every status is checked below instead (io/gsl_errors.hpp).

struct WorkspaceDeleter {
  void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};
using Workspace = std::unique_ptr<gsl_integration_workspace, WorkspaceDeleter>;

double diameter_from_mass(const Parameters& p, double mass) { return std::cbrt(6.0 * mass / (kPi * p.rho_particle)); }

std::string format(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

void check_burn_out(double tau, double burn_out) {
  if (tau >= burn_out)
    throw InputError("duration", format(tau), "at or past burn-out at tau_b = " + format(burn_out) + " s (d0/beta)");
}

// λ(t) = 6 k_a Nu(t) / (ρ_p c_s d(t)²) along the burning, decelerating particle (docs/model.md §4.6).
struct HeatRate {
  double d0, beta;
  double inverse_s0;                   // 1/s0
  double kappa_over_beta;              // κ/β
  double rate_factor;                  // 6 k_a / (ρ_p c_s)
  double nusselt_coefficient;          // 0.6 Pr^(1/3)
  double reynolds_per_speed_diameter;  // ρ_a / μ_a

  double operator()(double t) const {
    const double d = d0 - beta * t;
    const double u = -std::log1p(-beta * t / d0);  // ln(d0/d)
    const double s = 1.0 / (inverse_s0 + kappa_over_beta * u);
    const double nusselt = 2.0 + nusselt_coefficient * std::sqrt(reynolds_per_speed_diameter * s * d);
    return rate_factor * nusselt / (d * d);
  }
  static double call(double t, void* self) { return (*static_cast<const HeatRate*>(self))(t); }
};

// Λ(τ) = ∫₀^τ λ dt by QAG. For τ < 0 (an ODE-residual stencil reaching just before the launch)
// it integrates over [τ, 0] and changes the sign.
HeatExponent integrate_heat_rate(const HeatRate& rate, double tau) {
  use_gsl_return_codes();
  HeatExponent h;
  if (tau == 0.0) return h;
  const Workspace workspace(gsl_integration_workspace_alloc(kQuadratureIntervals));
  if (!workspace) {
    h.value = kNaN;
    h.status = GSL_ENOMEM;
    return h;
  }
  gsl_function f{&HeatRate::call, const_cast<HeatRate*>(&rate)};
  double result = 0.0, error = 0.0;
  const double lower = std::min(tau, 0.0), upper = std::max(tau, 0.0);
  h.status = gsl_integration_qag(&f, lower, upper, 0.0, kHeatQuadratureTolerance, kQuadratureIntervals,
                                 GSL_INTEG_GAUSS61, workspace.get(), &result, &error);
  h.intervals = workspace->size;
  h.value = tau < 0.0 ? -result : result;
  h.error = error;
  const bool accepted = h.status == GSL_SUCCESS || (std::isfinite(result) && error <= kHeatQuadratureAccepted * std::abs(result));
  if (!accepted) h.value = kNaN;
  return h;
}
}  // namespace

double burn_diameter_rate(const Parameters& parameters) {
  return 2.0 * parameters.burn_rate / (kPi * parameters.rho_particle);
}

double burn_out_time(const Parameters& parameters) {
  const double beta = burn_diameter_rate(parameters);
  return beta > 0.0 ? parameters.diameter / beta : std::numeric_limits<double>::infinity();
}

void check_before_burn_out(const Parameters& parameters, double tau) { check_burn_out(tau, burn_out_time(parameters)); }

HeatExponent burn_heat_exponent(const Physics& physics, const ParticleState& y0, double tau) {
  const Parameters& p = physics.parameters;
  const double beta = burn_diameter_rate(p);
  const double d0 = diameter_from_mass(p, y0[MASS]);
  if (beta > 0.0) check_burn_out(tau, d0 / beta);
  const double d = d0 - beta * tau;
  const double s0 = speed(y0);
  HeatExponent h;
  if (s0 == 0.0) {  // Nu = 2: Λ = (12 k_a/(ρ_p c_s β))(1/d − 1/d0) = 12 k_a τ / (ρ_p c_s d0 d)
    h.value = 12.0 * p.k_gas() * tau / (p.rho_particle * p.cs_particle * d0 * d);
    return h;
  }
  if (beta == 0.0) {  // not burning: docs/model.md §4.5 at the diameter the rates see
    Physics fixed = physics;
    fixed.parameters.diameter = d0;
    h.value = drag_heat_exponent(fixed, y0, tau);
    return h;
  }
  // κ = 0 without drag: then s = s0 throughout, and the same integrand applies.
  const double kappa = physics.terms.drag ? p.drag_kappa() : 0.0;
  const HeatRate rate{d0,
                      beta,
                      1.0 / s0,
                      kappa / beta,
                      6.0 * p.k_gas() / (p.rho_particle * p.cs_particle),
                      0.6 * std::cbrt(p.prandtl),
                      p.rho_gas / p.mu_gas};
  return integrate_heat_rate(rate, tau);
}

ParticleState burn(const Physics& physics, const ParticleState& y0, double tau) {
  const Parameters& p = physics.parameters;
  const double beta = burn_diameter_rate(p);
  if (!physics.terms.burning) return drag_heat(physics, y0, tau);
  const double d0 = diameter_from_mass(p, y0[MASS]);
  if (beta == 0.0) {  // c_b = 0: docs/model.md §4.3 (+ §4.5) at the diameter the rates see
    Physics fixed = physics;
    fixed.parameters.diameter = d0;
    return drag_heat(fixed, y0, tau);
  }
  check_burn_out(tau, d0 / beta);
  use_gsl_return_codes();

  ParticleState y = y0;
  const double shrink = beta * tau / d0;  // 1 − d/d0
  const double ratio = 1.0 - shrink;      // d/d0
  y[MASS] = y0[MASS] * ratio * ratio * ratio;

  const double s0 = speed(y0);
  if (s0 > 0.0 && !physics.terms.drag) {  // no drag: straight line at s0 (docs/model.md §4.1)
    for (int i = 0; i < 3; ++i) y[X + i] = y0[X + i] + y0[VX + i] * tau;
  } else if (s0 > 0.0) {
    const double kappa = p.drag_kappa();
    const double u = -std::log1p(-shrink);  // ln(d0/d)
    const double a = beta / (kappa * s0);
    const double speed_ratio = 1.0 / (1.0 + (kappa / beta) * u * s0);  // s/s0 = 1/(1 + (κ/β) u s0)
    gsl_sf_result e1_a, e1_au;
    const int status_a = gsl_sf_expint_E1_scaled_e(a, &e1_a);
    const int status_au = gsl_sf_expint_E1_scaled_e(a + u, &e1_au);
    const double distance = status_a == GSL_SUCCESS && status_au == GSL_SUCCESS
                                ? (d0 / kappa) * (e1_a.val - ratio * e1_au.val)
                                : kNaN;
    const double distance_per_speed = distance / s0;  // ‖x − x0‖ / s0
    for (int i = 0; i < 3; ++i) {
      y[X + i] = y0[X + i] + y0[VX + i] * distance_per_speed;
      y[VX + i] = y0[VX + i] * speed_ratio;
    }
  }
  if (physics.terms.heat) {
    const double t_gas = p.t_gas;
    y[TEMPERATURE] = t_gas + (y0[TEMPERATURE] - t_gas) * std::exp(-burn_heat_exponent(physics, y0, tau).value);
  }
  return y;
}

}  // namespace dlpverify::dlp::exact
