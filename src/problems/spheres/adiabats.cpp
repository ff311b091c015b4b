#include "problems/spheres/adiabats.hpp"

#include <cmath>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/gsl_errors.hpp"

namespace dlpverify::compress {

double ideal_adiabat(double volume_ratio) { return std::cbrt(volume_ratio * volume_ratio); }

double collisionless_one_axis(double length_ratio) { return (length_ratio * length_ratio + 2.0) / 3.0; }

double carnahan_starling_z(double packing) {
  const double e = packing, q = 1.0 - e;
  return (1.0 + e + e * e - e * e * e) / (q * q * q);
}

namespace {

void check_packing(double packing1, double volume_ratio) {
  if (!(packing1 >= 0.0 && packing1 * volume_ratio < 1.0 && volume_ratio > 0.0))
    throw InputError("packing fraction", value_text(packing1), "the compressed packing fraction must stay below 1");
}

int rhs(double x, const double*, double* dydx, void* params) {
  const double packing1 = *static_cast<const double*>(params);
  dydx[0] = 2.0 / 3.0 * carnahan_starling_z(packing1 * std::exp(x));
  return GSL_SUCCESS;
}

double excess_free_energy(double e) { return (4.0 * e - 3.0 * e * e) / ((1.0 - e) * (1.0 - e)); }

}  // namespace

double carnahan_starling_adiabat(double packing1, double volume_ratio) {
  check_packing(packing1, volume_ratio);
  use_gsl_return_codes();
  double params = packing1;
  gsl_odeiv2_system system{rhs, nullptr, 1, &params};
  gsl_odeiv2_driver* driver = gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-6, 1e-14, 1e-12);
  double x = 0.0, y[1] = {0.0};  // y = ln(T/T1)
  const int status = gsl_odeiv2_driver_apply(driver, &x, std::log(volume_ratio), y);
  gsl_odeiv2_driver_free(driver);
  if (status != GSL_SUCCESS) throw SolverError(std::string("Carnahan-Starling adiabat: GSL odeiv2 failed: ") + gsl_strerror(status));
  return std::exp(y[0]);
}

double carnahan_starling_adiabat_closed_form(double packing1, double volume_ratio) {
  check_packing(packing1, volume_ratio);
  const double packing2 = packing1 * volume_ratio;
  return std::exp(2.0 / 3.0 * (std::log(volume_ratio) + excess_free_energy(packing2) - excess_free_energy(packing1)));
}

}  // namespace dlpverify::compress
