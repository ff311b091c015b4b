#include "dlpverify/norms.hpp"

#include <cmath>

#include "dlpverify/extended.hpp"
#include "harness/compensated_sum.hpp"
#include "harness/distribution.hpp"

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

// A block's partial as the doubles every process sends (harness/distribution.hpp), and back.
constexpr std::size_t kPartialDoubles = 5;

std::vector<NormSums> every_process(const std::vector<NormSums>& own) {
  std::vector<double> sent;
  for (const NormSums& p : own)
    sent.insert(sent.end(), {p.error.sum, p.error.compensation, p.reference.sum, p.reference.compensation, p.largest});
  const std::vector<double> all = distribution().all_gathered(sent);
  std::vector<NormSums> partials(all.size() / kPartialDoubles);
  for (std::size_t b = 0; b < partials.size(); ++b) {
    const double* p = &all[b * kPartialDoubles];
    partials[b].error = {p[0], p[1]};
    partials[b].reference = {p[2], p[3]};
    partials[b].largest = p[4];
  }
  return partials;
}

// The sums over every member: this process's block partials, under MPI those of every process in
// rank order (each holds whole blocks in global order, harness/distribution.hpp), combined in
// block order — the serial run's bits for any number of processes and threads.
// difference(p, f) is a(p, f) − b(p, f) and size(p, f) is b(p, f), each as a double.
template <class Difference, class Size>
NormSums norm_sums(Eigen::Index members, const Variable& variable, Difference difference, Size size) {
  std::vector<NormSums> partials =
      blocked_partials<NormSums>(members, [&](Eigen::Index first, Eigen::Index count, NormSums& partial) {
        for (Eigen::Index p = first; p < first + count; ++p) {
          double e2 = 0.0, r2 = 0.0;
          for (int f = variable.first_field; f < variable.first_field + variable.fields; ++f) {
            const double d = difference(p, f), r = size(p, f);
            e2 += d * d;
            r2 += r * r;
          }
          partial.error.add(e2);
          partial.reference.add(r2);
          partial.add_largest(e2);
        }
      });
  if (distribution().ranks() > 1) partials = every_process(partials);
  NormSums total;
  for (const NormSums& partial : partials) total.add(partial);
  return total;
}

ErrorNorms norms_of(const NormSums& sums, Eigen::Index own_members) {
  ErrorNorms norms;
  const Eigen::Index members = distribution().sum(static_cast<long>(own_members));
  if (members == 0) return norms;
  norms.l2 = std::sqrt(sums.error.value());
  norms.rms = norms.l2 / std::sqrt(static_cast<double>(members));
  norms.reference_l2 = std::sqrt(sums.reference.value());
  norms.relative = norms.reference_l2 > 0.0 ? norms.l2 / norms.reference_l2 : norms.l2;
  norms.max = std::sqrt(sums.largest);  // √ is monotonic: the largest member error
  return norms;
}

}  // namespace

Eigen::ArrayXd member_errors(const State& numerical, const State& reference, const Variable& variable) {
  const auto difference = numerical.middleCols(variable.first_field, variable.fields) -
                          reference.middleCols(variable.first_field, variable.fields);
  return difference.square().rowwise().sum().sqrt();
}

ErrorNorms error_norms(const State& numerical, const State& reference, const Variable& variable) {
  const NormSums sums = norm_sums(  // every process takes part
      numerical.rows(), variable, [&](Eigen::Index p, int f) { return numerical(p, f) - reference(p, f); },
      [&](Eigen::Index p, int f) { return reference(p, f); });
  return norms_of(sums, numerical.rows());
}

// The difference is taken in Extended and rounded once: an error of 1e-25 next to values of 1 keeps
// its digits, where the doubles' difference would be round-off.
ErrorNorms error_norms(const ExtendedState& numerical, const ExtendedState& reference, const Variable& variable) {
  const NormSums sums = norm_sums(
      numerical.rows(), variable, [&](Eigen::Index p, int f) { return to_double(numerical(p, f) - reference(p, f)); },
      [&](Eigen::Index p, int f) { return to_double(reference(p, f)); });
  return norms_of(sums, numerical.rows());
}

}  // namespace dlpverify
