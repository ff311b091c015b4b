// Error norms of SPEC §5 (seed eqs. 33–34) for one group of fields, e.g. position (x, y, z).
//
//   |e| = √(Σ_p ‖y_p − y_p(t)‖²)     absolute L2: grows like √N
//   rms = |e| / √N,   relative = |e| / √(Σ_p ‖y_p(t)‖²),   max = max_p ‖y_p − y_p(t)‖
#pragma once

#include <string>
#include <vector>

#include "problems/dlp/cloud.hpp"

namespace dlpverify {

// A group of consecutive fields measured together, e.g. {"position", X, 3, "m"}.
struct VariableGroup {
  std::string name;
  int first_field;
  int fields;
  std::string unit;
};

// The groups a study measures: position and velocity always, T and m when their terms are on.
std::vector<VariableGroup> measured_variables(const Terms& terms);

struct ErrorNorms {
  double l2 = 0.0;
  double rms = 0.0;
  double relative = 0.0;
  double max = 0.0;
  double reference_l2 = 0.0;  // √(Σ_p ‖y_p(t)‖²), the solution's own size
};

ErrorNorms error_norms(const CloudArray& numerical, const CloudArray& reference, const VariableGroup& group);

// Per-particle error ‖y_p − y_p(t)‖ of one group.
Eigen::ArrayXd particle_errors(const CloudArray& numerical, const CloudArray& reference, const VariableGroup& group);

}  // namespace dlpverify
