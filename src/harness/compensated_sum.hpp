// Sums over a population that neither lose digits nor depend on the thread count.
//
// Neumaier's compensated sum (Kahan–Babuška): each addition s + x also recovers the part of x (or
// of s) that the rounded sum lost, and keeps it in c; the result is s + c. Its error is at most
// about 2 ε |Σx| + O(n ε²) Σ|x| (Higham, Accuracy and Stability of Numerical Algorithms, §4.3),
// where naive recursive summation may lose (n − 1) ε Σ|x|: on 4 M particles × 3 fields that is
// the difference between the last bit and the fifth-to-last digit of an error norm.
//
// blocked_sum splits the terms into fixed blocks of kSumBlock members, sums each block into a
// partial of its own (in parallel: the block, not the thread, is the unit of work), and combines
// the partials in block order. Neither the blocks nor the order depend on the number of threads,
// so every bit of the result is the same for any --threads.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "dlpverify/eigen.hpp"

namespace dlpverify {

struct NeumaierSum {
  double sum = 0.0;
  double compensation = 0.0;  // what the rounded additions to `sum` lost

  void add(double x) {
    const double t = sum + x;
    // The smaller of the two operands is the one whose low-order digits the rounding dropped.
    if (std::abs(sum) >= std::abs(x))
      compensation += (sum - t) + x;
    else
      compensation += (x - t) + sum;
    sum = t;
  }
  // Adds another partial sum: its rounded part compensated, its compensation as it is.
  void add(const NeumaierSum& partial) {
    add(partial.sum);
    compensation += partial.compensation;
  }
  double value() const { return sum + compensation; }
};

// Members per block of blocked_sum: a fixed number, so that the blocks do not follow the threads.
inline constexpr Eigen::Index kSumBlock = 4096;

// The partial sums of members 0 … n − 1 in fixed blocks, in block order: add_terms(first, count,
// partial) adds the terms of members first … first + count − 1 to `partial`, in member order,
// called concurrently on disjoint blocks.
template <class Partial, class AddTerms>
std::vector<Partial> blocked_partials(Eigen::Index n, const AddTerms& add_terms) {
  if (n <= 0) return {};
  const Eigen::Index blocks = (n + kSumBlock - 1) / kSumBlock;
  std::vector<Partial> partials(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(static) if (blocks > 1)
  for (Eigen::Index b = 0; b < blocks; ++b) {
    const Eigen::Index first = b * kSumBlock;
    add_terms(first, std::min(kSumBlock, n - first), partials[static_cast<std::size_t>(b)]);
  }
  return partials;
}

// A reduction over members 0 … n − 1 in fixed blocks (blocked_partials), the partials combined
// with Partial::add in block order, whatever the threads.
template <class Partial, class AddTerms>
Partial blocked_reduce(Eigen::Index n, const AddTerms& add_terms) {
  Partial total;
  for (const Partial& partial : blocked_partials<Partial>(n, add_terms)) total.add(partial);
  return total;
}

// Σ over members 0 … n − 1 of the terms add_terms adds to a NeumaierSum (blocked_reduce).
template <class AddTerms>
double blocked_sum(Eigen::Index n, const AddTerms& add_terms) {
  return blocked_reduce<NeumaierSum>(n, add_terms).value();
}

}  // namespace dlpverify
