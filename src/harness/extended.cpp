#include "dlpverify/extended.hpp"

#include <algorithm>
#include <vector>

#include "dlpverify/evaluate_rhs.hpp"
#include "dlpverify/first_failure.hpp"

namespace dlpverify {

std::string to_string(Precision precision) { return precision == Precision::extended ? "extended" : "double"; }

double epsilon_of(Precision precision) {
  return precision == Precision::extended ? kExtendedEpsilon : kDoubleEpsilon;
}

ExtendedState::ExtendedState(Eigen::Index members, int fields)
    : rows_(members), cols_(fields), values_(static_cast<std::size_t>(members) * static_cast<std::size_t>(fields), Extended(0.0)) {}

ExtendedState::ExtendedState(const State& state) : ExtendedState(state.rows(), static_cast<int>(state.cols())) {
  for (int f = 0; f < cols_; ++f)
    for (Eigen::Index p = 0; p < rows_; ++p) (*this)(p, f) = Extended(state(p, f));
}

ExtendedState ExtendedState::rows_of(Eigen::Index first, Eigen::Index count) const {
  ExtendedState part(count, cols_);
  for (int f = 0; f < cols_; ++f) std::copy_n(col(f) + first, count, part.col(f));
  return part;
}

State ExtendedState::high() const {
  State state(rows_, cols_);
  for (int f = 0; f < cols_; ++f)
    for (Eigen::Index p = 0; p < rows_; ++p) state(p, f) = (*this)(p, f).x[0];  // a normalised double-double: its nearest double
  return state;
}

State ExtendedState::low() const {
  State state(rows_, cols_);
  for (int f = 0; f < cols_; ++f)
    for (Eigen::Index p = 0; p < rows_; ++p) state(p, f) = (*this)(p, f).x[1];
  return state;
}

void evaluate_extended_rhs(const ExtendedRhs& rhs, const Extended& t, const ExtendedState& state, ExtendedState& rates) {
  const Eigen::Index n = state.rows();
  const int fields = state.cols();
  if (rates.rows() != n || rates.cols() != fields) rates = ExtendedState(n, fields);
  const Eigen::Index blocks = (n + kRhsBlock - 1) / kRhsBlock;
  FirstFailure failure;  // a problem's rhs may throw; it must not leave the parallel region
#pragma omp parallel if (blocks > 1)
  {
    std::vector<const Extended*> in(static_cast<std::size_t>(fields));
    std::vector<Extended*> out(static_cast<std::size_t>(fields));
#pragma omp for schedule(static)
    for (Eigen::Index b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * kRhsBlock;
      for (int f = 0; f < fields; ++f) {
        in[static_cast<std::size_t>(f)] = state.col(f) + first;
        out[static_cast<std::size_t>(f)] = rates.col(f) + first;
      }
      try {
        rhs.rhs(t, first, static_cast<int>(std::min(kRhsBlock, n - first)), in.data(), out.data());
      } catch (...) {
        failure.capture();
      }
    }
  }
  failure.rethrow();
}

}  // namespace dlpverify
