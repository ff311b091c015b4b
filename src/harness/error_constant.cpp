#include "dlpverify/error_constant.hpp"

#include <cmath>
#include <limits>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

#include "io/gsl_errors.hpp"

namespace dlpverify {

ErrorConstant fit_error_constant(const std::vector<double>& dt, const std::vector<double>& error,
                                 const std::vector<int>& levels, double order) {
  ErrorConstant constant;
  constant.order = order;
  constant.levels = levels;
  const std::size_t n = levels.size();
  if (n == 0 || !(order > 0.0)) return constant;
  // ln C_k = ln e_k − p ln Δt_k: the intercept of the order fit's line with its slope held at p.
  std::vector<double> log_constant(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double e = error[levels[i]];
    if (!std::isfinite(e) || !(e > 0.0)) return constant;
    log_constant[i] = std::log(e) - order * std::log(dt[levels[i]]);
  }
  use_gsl_return_codes();  // as the order fit: never abort()
  const double mean = gsl_stats_mean(log_constant.data(), 1, n);
  constant.valid = true;
  constant.value = std::exp(mean);
  if (n > 1) {
    constant.log_stderr = gsl_stats_sd_m(log_constant.data(), 1, n, mean) / std::sqrt(static_cast<double>(n));
    const double t = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(n - 1));
    constant.ci_low = std::exp(mean - t * constant.log_stderr);
    constant.ci_high = std::exp(mean + t * constant.log_stderr);
  } else {
    constant.log_stderr = constant.ci_low = constant.ci_high = std::numeric_limits<double>::quiet_NaN();
  }
  return constant;
}

}  // namespace dlpverify
