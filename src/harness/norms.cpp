#include "dlpverify/norms.hpp"

#include <cmath>

namespace dlpverify {

Eigen::ArrayXd member_errors(const State& numerical, const State& reference, const Variable& variable) {
  const auto difference = numerical.middleCols(variable.first_field, variable.fields) -
                          reference.middleCols(variable.first_field, variable.fields);
  return difference.square().rowwise().sum().sqrt();
}

ErrorNorms error_norms(const State& numerical, const State& reference, const Variable& variable) {
  ErrorNorms norms;
  const Eigen::Index members = numerical.rows();
  if (members == 0) return norms;
  const auto difference = numerical.middleCols(variable.first_field, variable.fields) -
                          reference.middleCols(variable.first_field, variable.fields);
  norms.l2 = std::sqrt(difference.square().sum());
  norms.rms = norms.l2 / std::sqrt(static_cast<double>(members));
  norms.reference_l2 = std::sqrt(reference.middleCols(variable.first_field, variable.fields).square().sum());
  norms.relative = norms.reference_l2 > 0.0 ? norms.l2 / norms.reference_l2 : norms.l2;
  norms.max = std::sqrt(difference.square().rowwise().sum().maxCoeff());
  return norms;
}

}  // namespace dlpverify
