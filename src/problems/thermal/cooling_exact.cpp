#include "problems/thermal/cooling_exact.hpp"

#include <cmath>
#include <limits>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "dlpverify/errors.hpp"

namespace dlpverify::thermal {

namespace {

// θ_s³ F(θ): scaled so that its values are of order one.
double scaled_antiderivative(double theta, double theta_s) {
  return 0.25 * std::log(std::abs((theta - theta_s) / (theta + theta_s))) - 0.5 * std::atan(theta / theta_s);
}

struct RadiationRoot {
  double theta0, theta_s, beta_t_scaled;  // β θ_s³ t
};

// G(θ) = θ_s³ (F(θ0) − F(θ)) − β θ_s³ t: zero at the solution, of one sign between it and θ_s.
double residual(double theta, void* data) {
  const auto& r = *static_cast<const RadiationRoot*>(data);
  return scaled_antiderivative(r.theta0, r.theta_s) - scaled_antiderivative(theta, r.theta_s) - r.beta_t_scaled;
}

}  // namespace

double radiation_to_surroundings(double theta0, double beta, double theta_s, double t) {
  if (theta0 == theta_s || t == 0.0) return theta0;
  RadiationRoot root{theta0, theta_s, beta * theta_s * theta_s * theta_s * t};
  // θ lies between θ0 and θ_s; next to θ_s, G has the sign of the far future.
  const double near_s = std::nextafter(theta_s, theta0);
  if (residual(near_s, &root) * residual(theta0, &root) > 0.0) return near_s;  // at θ_s to double precision
  gsl_function g{&residual, &root};
  gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(solver, &g, std::min(near_s, theta0), std::max(near_s, theta0));
  int status = GSL_CONTINUE;
  double theta = theta0;
  for (int i = 0; i < 200 && status == GSL_CONTINUE; ++i) {
    gsl_root_fsolver_iterate(solver);
    theta = gsl_root_fsolver_root(solver);
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver), gsl_root_fsolver_x_upper(solver), 0.0,
                                    4.0 * std::numeric_limits<double>::epsilon());
  }
  gsl_root_fsolver_free(solver);
  if (status != GSL_SUCCESS) throw SolverError("radiative cooling: the root solve for the temperature did not converge");
  return theta;
}

double radiation_to_vacuum(double theta0, double beta, double t) {
  return theta0 * std::cbrt(1.0 / (1.0 + 3.0 * beta * theta0 * theta0 * theta0 * t));
}

double convection_and_radiation_to_zero(double theta0, double alpha, double beta, double t) {
  // u = θ0⁻³ e^(3αt) + (β/α)(e^(3αt) − 1), with expm1 so that small αt loses nothing
  const double u = std::exp(3.0 * alpha * t) / (theta0 * theta0 * theta0) + beta / alpha * std::expm1(3.0 * alpha * t);
  return 1.0 / std::cbrt(u);
}

}  // namespace dlpverify::thermal
