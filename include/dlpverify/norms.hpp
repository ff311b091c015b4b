/// @file
/// Error norms of docs/model.md §5 (the seed's eqs. 33–34) for one measured variable, e.g.
/// position (x, y, z):
///
/// @code{.unparsed}
///   |e| = √(Σ_p ‖y_p − y_p(t)‖²)     absolute L2: grows like √N
///   rms = |e| / √N,   relative = |e| / √(Σ_p ‖y_p(t)‖²),   max = max_p ‖y_p − y_p(t)‖
/// @endcode
///
/// The sums are compensated (Neumaier) over fixed blocks of members combined in block order
/// (src/harness/compensated_sum.hpp): accurate to a few ulp for any N, the same bits for any
/// number of threads.
#pragma once

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// The error of one measured variable over the population, against the reference.
struct ErrorNorms {
  double l2 = 0.0;        ///< |e| = √(Σ_p ‖y_p − y_p(t)‖²), absolute L2
  double rms = 0.0;       ///< |e| / √N
  double relative = 0.0;  ///< |e| / √(Σ_p ‖y_p(t)‖²)
  double max = 0.0;       ///< max_p ‖y_p − y_p(t)‖
  double reference_l2 = 0.0;  ///< √(Σ_p ‖y_p(t)‖²), the solution's own size
};

/// The norms of `numerical` − `reference` over the fields of `variable` (both N × F, compensated sums).
ErrorNorms error_norms(const State& numerical, const State& reference, const Variable& variable);

class ExtendedState;
/// The same for states in Extended (dlpverify/extended.hpp): each difference is taken in Extended
/// and rounded to double once, so an error far below double's ε ‖y‖ is measured, not rounded away.
ErrorNorms error_norms(const ExtendedState& numerical, const ExtendedState& reference, const Variable& variable);

/// Per-member error ‖y_p − y_p(t)‖ of one variable.
Eigen::ArrayXd member_errors(const State& numerical, const State& reference, const Variable& variable);

}  // namespace dlpverify
