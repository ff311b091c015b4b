#include "dlpverify/extended.hpp"

#include <algorithm>

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

}  // namespace dlpverify
