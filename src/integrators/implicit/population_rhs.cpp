#include "integrators/implicit/population_rhs.hpp"

#include <algorithm>
#include <vector>

#include "dlpverify/splitting.hpp"

namespace dlpverify::implicit {

namespace {
constexpr Eigen::Index kBlock = 256;  // members per right-hand-side call
}

void population_rhs(const Problem& problem, double t, const State& y, State& dydt) {
  const Eigen::Index n = y.rows();
  const int fields = static_cast<int>(y.cols());
  dydt.resize(n, fields);
  const Eigen::Index blocks = (n + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static) if (blocks > 4)
  for (Eigen::Index b = 0; b < blocks; ++b) {
    const Eigen::Index first = b * kBlock;
    const int count = static_cast<int>(std::min(kBlock, n - first));
    std::vector<const double*> in(static_cast<std::size_t>(fields));
    std::vector<double*> out(static_cast<std::size_t>(fields));
    for (int f = 0; f < fields; ++f) {
      in[static_cast<std::size_t>(f)] = y.col(f).data() + first;
      out[static_cast<std::size_t>(f)] = dydt.col(f).data() + first;
    }
    problem.rhs(t, first, count, in.data(), out.data());
  }
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
