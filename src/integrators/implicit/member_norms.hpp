// Each member's Euclidean norm over some of its fields, each field in units of its size
// (field_scales): how the implicit schemes weigh fields of different units in one measure.
#pragma once

#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify::implicit {

// ‖a_p − c_p‖ of every member p over fields first … first + count − 1, each divided by its size.
inline Eigen::ArrayXd member_norms(const State& a, const State& c, const std::vector<double>& size, int first,
                                   int count) {
  Eigen::ArrayXd squares = Eigen::ArrayXd::Zero(a.rows());
  for (int f = first; f < first + count; ++f) squares += ((a.col(f) - c.col(f)) / size[static_cast<std::size_t>(f)]).square();
  return squares.sqrt();
}

// ‖a_p‖ likewise.
inline Eigen::ArrayXd member_norms(const State& a, const std::vector<double>& size, int first, int count) {
  Eigen::ArrayXd squares = Eigen::ArrayXd::Zero(a.rows());
  for (int f = first; f < first + count; ++f) squares += (a.col(f) / size[static_cast<std::size_t>(f)]).square();
  return squares.sqrt();
}

}  // namespace dlpverify::implicit
