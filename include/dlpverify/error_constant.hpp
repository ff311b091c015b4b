/// @file
/// The error constant C of e ≈ C Δt^p, fitted with the order p fixed: the expected order, or
/// the integer the fitted order names when it is another (error_constant_order, dlpverify/order.hpp;
/// docs/verification.md, "The error constant"). Two methods of one order differ in C, not in
/// p: a wrong weight in an order-2 family keeps the slope and moves the constant.
#pragma once

#include <vector>

namespace dlpverify {

/// C of e ≈ C Δt^p with p fixed, over some levels k (n of them):
/// @code{.unparsed}
///   ln C  = (1/n) Σ_k (ln e_k − p ln Δt_k)                      the mean of the per-level ln C_k
///   s     = √(Σ_k (ln C_k − ln C)² / (n − 1))                    their scatter
///   95%   = [C exp(−t s/√n), C exp(+t s/√n)],  t = t_{0.975, n−1}  (Student's t)
/// @endcode
/// The interval is multiplicative: ln C is what is fitted. Its unit is the error's over Δt^p.
struct ErrorConstant {
  bool valid = false;      ///< at least one level was fitted
  double order = 0.0;      ///< p, held fixed
  double value = 0.0;      ///< C
  double log_stderr = 0.0; ///< s/√n, the standard error of ln C (NaN with one level)
  double ci_low = 0.0,     ///< low end of the 95% interval, C exp(−t s/√n) (NaN with one level)
      ci_high = 0.0;       ///< high end of the 95% interval, C exp(+t s/√n) (NaN with one level)
  std::vector<int> levels; ///< the levels fitted
};

/// C of e ≈ C Δt^order over the indices in `levels` of `dt` and `error`; invalid with no level,
/// a non-positive order, or an error that is not finite and positive at a fitted level.
ErrorConstant fit_error_constant(const std::vector<double>& dt, const std::vector<double>& error,
                                 const std::vector<int>& levels, double order);

}  // namespace dlpverify
