#include "dlpverify/evaluate_rhs.hpp"

#include <algorithm>
#include <vector>

#include "dlpverify/first_failure.hpp"

namespace dlpverify {

void evaluate_rhs(const Problem& problem, double t, const State& state, State& rates) {
  check_shape(problem, state, "the state of evaluate_rhs");
  const Eigen::Index n = state.rows();
  const int fields = static_cast<int>(state.cols());
  rates.resize(n, fields);
  const Eigen::Index blocks = (n + kRhsBlock - 1) / kRhsBlock;
  // A parallel region costs a fork and a barrier per evaluation: worth it from a few blocks on.
  FirstFailure failure;  // a problem's rhs may throw; it must not leave the parallel region
#pragma omp parallel if (blocks > 4)
  {
    std::vector<const double*> in(static_cast<std::size_t>(fields));
    std::vector<double*> out(static_cast<std::size_t>(fields));
#pragma omp for schedule(static)
    for (Eigen::Index b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * kRhsBlock;
      for (int f = 0; f < fields; ++f) {
        in[static_cast<std::size_t>(f)] = state.col(f).data() + first;
        out[static_cast<std::size_t>(f)] = rates.col(f).data() + first;
      }
      try {
        problem.rhs(t, first, static_cast<int>(std::min(kRhsBlock, n - first)), in.data(), out.data());
      } catch (...) {
        failure.capture();
      }
    }
  }
  failure.rethrow();
}

}  // namespace dlpverify
