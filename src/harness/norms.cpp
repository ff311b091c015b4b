#include "harness/norms.hpp"

#include <cmath>

namespace dlpverify {

std::vector<VariableGroup> measured_variables(const Terms& terms) {
  std::vector<VariableGroup> groups{{"position", X, 3, "m"}, {"velocity", VX, 3, "m/s"}};
  if (terms.heat) groups.push_back({"temperature", TEMPERATURE, 1, "K"});
  if (terms.burning) groups.push_back({"mass", MASS, 1, "kg"});
  return groups;
}

Eigen::ArrayXd particle_errors(const CloudArray& numerical, const CloudArray& reference, const VariableGroup& group) {
  const auto difference = numerical.middleCols(group.first_field, group.fields) -
                          reference.middleCols(group.first_field, group.fields);
  return difference.square().rowwise().sum().sqrt();
}

ErrorNorms error_norms(const CloudArray& numerical, const CloudArray& reference, const VariableGroup& group) {
  ErrorNorms norms;
  const Eigen::Index particles = numerical.rows();
  if (particles == 0) return norms;
  const auto difference = numerical.middleCols(group.first_field, group.fields) -
                          reference.middleCols(group.first_field, group.fields);
  norms.l2 = std::sqrt(difference.square().sum());
  norms.rms = norms.l2 / std::sqrt(static_cast<double>(particles));
  norms.reference_l2 = std::sqrt(reference.middleCols(group.first_field, group.fields).square().sum());
  norms.relative = norms.reference_l2 > 0.0 ? norms.l2 / norms.reference_l2 : norms.l2;
  norms.max = std::sqrt(difference.square().rowwise().sum().maxCoeff());
  return norms;
}

}  // namespace dlpverify
