// Error norms of docs/model.md §5 (the seed's eqs. 33–34) for one measured variable, e.g.
// position (x, y, z):
//
//   |e| = √(Σ_p ‖y_p − y_p(t)‖²)     absolute L2: grows like √N
//   rms = |e| / √N,   relative = |e| / √(Σ_p ‖y_p(t)‖²),   max = max_p ‖y_p − y_p(t)‖
//
// The sums are compensated (Neumaier) over fixed blocks of members combined in block order
// (src/harness/compensated_sum.hpp): accurate to a few ulp for any N, the same bits for any
// number of threads.
#pragma once

#include "dlpverify/problem.hpp"

namespace dlpverify {

struct ErrorNorms {
  double l2 = 0.0;
  double rms = 0.0;
  double relative = 0.0;
  double max = 0.0;
  double reference_l2 = 0.0;  // √(Σ_p ‖y_p(t)‖²), the solution's own size
};

ErrorNorms error_norms(const State& numerical, const State& reference, const Variable& variable);

// Per-member error ‖y_p − y_p(t)‖ of one variable.
Eigen::ArrayXd member_errors(const State& numerical, const State& reference, const Variable& variable);

}  // namespace dlpverify
