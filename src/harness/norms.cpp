#include "dlpverify/norms.hpp"

#include <cmath>

#include "harness/compensated_sum.hpp"

namespace dlpverify {

namespace {

// Σ_p Σ_f (a(p, f) − b(p, f))² over the variable's fields (Σ a² without b): compensated, in
// fixed blocks of members, so neither N nor the thread count costs a digit or changes a bit.
double sum_of_squares(const State& a, const State* b, const Variable& variable) {
  return blocked_sum(a.rows(), [&](Eigen::Index first, Eigen::Index count, NeumaierSum& partial) {
    for (int f = variable.first_field; f < variable.first_field + variable.fields; ++f)
      for (Eigen::Index p = first; p < first + count; ++p) {
        const double d = b ? a(p, f) - (*b)(p, f) : a(p, f);
        partial.add(d * d);
      }
  });
}

}  // namespace

Eigen::ArrayXd member_errors(const State& numerical, const State& reference, const Variable& variable) {
  const auto difference = numerical.middleCols(variable.first_field, variable.fields) -
                          reference.middleCols(variable.first_field, variable.fields);
  return difference.square().rowwise().sum().sqrt();
}

ErrorNorms error_norms(const State& numerical, const State& reference, const Variable& variable) {
  ErrorNorms norms;
  const Eigen::Index members = numerical.rows();
  if (members == 0) return norms;
  norms.l2 = std::sqrt(sum_of_squares(numerical, &reference, variable));
  norms.rms = norms.l2 / std::sqrt(static_cast<double>(members));
  norms.reference_l2 = std::sqrt(sum_of_squares(reference, nullptr, variable));
  norms.relative = norms.reference_l2 > 0.0 ? norms.l2 / norms.reference_l2 : norms.l2;
  // The largest member error is exact in any order.
  norms.max = member_errors(numerical, reference, variable).maxCoeff();
  return norms;
}

}  // namespace dlpverify
