#include "dlpverify/norms.hpp"

#include <cmath>

#include "harness/compensated_sum.hpp"

namespace dlpverify {

namespace {

// One pass over the members for the norms of one variable: Σ_p ‖a_p − b_p‖² and Σ_p ‖b_p‖²,
// compensated, and max_p ‖a_p − b_p‖² (NaN once any member's is NaN, so a broken member is
// never hidden). A member's squares are summed over the variable's fields first.
struct NormSums {
  NeumaierSum error, reference;
  double largest = 0.0;
  void add_largest(double e2) {
    if (std::isnan(e2) || e2 > largest) largest = std::isnan(largest) ? largest : e2;
  }
  void add(const NormSums& partial) {
    error.add(partial.error);
    reference.add(partial.reference);
    add_largest(partial.largest);
  }
};

NormSums norm_sums(const State& a, const State& b, const Variable& variable) {
  return blocked_reduce<NormSums>(a.rows(), [&](Eigen::Index first, Eigen::Index count, NormSums& partial) {
    for (Eigen::Index p = first; p < first + count; ++p) {
      double e2 = 0.0, r2 = 0.0;
      for (int f = variable.first_field; f < variable.first_field + variable.fields; ++f) {
        const double d = a(p, f) - b(p, f);
        e2 += d * d;
        r2 += b(p, f) * b(p, f);
      }
      partial.error.add(e2);
      partial.reference.add(r2);
      partial.add_largest(e2);
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
  const NormSums sums = norm_sums(numerical, reference, variable);
  norms.l2 = std::sqrt(sums.error.value());
  norms.rms = norms.l2 / std::sqrt(static_cast<double>(members));
  norms.reference_l2 = std::sqrt(sums.reference.value());
  norms.relative = norms.reference_l2 > 0.0 ? norms.l2 / norms.reference_l2 : norms.l2;
  norms.max = std::sqrt(sums.largest);  // √ is monotonic: the largest member error
  return norms;
}

}  // namespace dlpverify
