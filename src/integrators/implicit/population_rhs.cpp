#include "integrators/implicit/population_rhs.hpp"

#include <algorithm>
#include <vector>

#include "dlpverify/splitting.hpp"

namespace dlpverify::implicit {

namespace {
constexpr Eigen::Index kBlock = 256;  // members per linear_decay call
}

State population_linear_decay(const Problem& problem) {
  const LinearDecay* decay = problem.capability<LinearDecay>();
  if (!decay) return State();
  const Eigen::Index n = problem.members();
  const int fields = problem.field_count();
  State lambda = State::Zero(n, fields);
  std::vector<double*> out(static_cast<std::size_t>(fields));
  for (Eigen::Index first = 0; first < n; first += kBlock) {
    for (int f = 0; f < fields; ++f) out[static_cast<std::size_t>(f)] = lambda.col(f).data() + first;
    decay->linear_decay(first, static_cast<int>(std::min(kBlock, n - first)), out.data());
  }
  return lambda;
}

}  // namespace dlpverify::implicit
