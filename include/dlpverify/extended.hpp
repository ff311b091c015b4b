/// @file
/// Extended precision's arithmetic: Extended is QD's
/// double-double (Debian's libqd-dev), a value an unevaluated sum of two doubles, 106 bits of
/// significand, about 32 significant digits, with elementary functions (sqrt, exp, log, sin, cos,
/// …) accurate to a few units of its last place. In it, double precision's round-off floor
/// ½ ε √n ‖y‖ moves from ε = 2^−52 to ε = 2^−104. It needs IEEE double arithmetic without fused
/// contractions the source did not write, which the project's flags keep (-ffp-contract=off, never
/// -ffast-math).
#pragma once

#include <string>
#include <vector>

#include <qd/dd_real.h>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// The extended arithmetic: QD's double-double (about 32 significant digits).
using Extended = dd_real;

/// Machine epsilon of double, 2^−52: the round-off floor ½ ε √n ‖y‖ (dlpverify/order.hpp).
inline constexpr double kDoubleEpsilon = 0x1p-52;
/// Machine epsilon of Extended, 2^−104 (QD's dd_real::_eps to its 15 printed digits).
inline constexpr double kExtendedEpsilon = 0x1p-104;

/// The arithmetic a study's levels (and its reference) are computed in.
enum class Precision {
  double_precision,  ///< IEEE double, the default
  extended,          ///< Extended (double-double)
};
/// "double" or "extended".
std::string to_string(Precision precision);
/// The machine epsilon of `precision`: kDoubleEpsilon or kExtendedEpsilon.
double epsilon_of(Precision precision);

/// A population's state in Extended: N members × F fields, column-major as State (field f of
/// member p at f·N + p).
class ExtendedState {
 public:
  ExtendedState() = default;
  /// N × F zeros.
  ExtendedState(Eigen::Index members, int fields);
  /// `state`'s values, exactly (a double is an Extended).
  explicit ExtendedState(const State& state);
  Eigen::Index rows() const { return rows_; }  ///< N
  int cols() const { return cols_; }           ///< F
  /// Field f's column of N values.
  Extended* col(int f) { return values_.data() + static_cast<std::size_t>(f) * static_cast<std::size_t>(rows_); }
  /// Field f's column of N values.
  const Extended* col(int f) const {
    return values_.data() + static_cast<std::size_t>(f) * static_cast<std::size_t>(rows_);
  }
  /// Field f of member p.
  Extended& operator()(Eigen::Index p, int f) { return col(f)[p]; }
  /// Field f of member p.
  const Extended& operator()(Eigen::Index p, int f) const { return col(f)[p]; }
  /// Members first … first + count − 1.
  ExtendedState rows_of(Eigen::Index first, Eigen::Index count) const;
  /// Every value rounded to the nearest double: the leading part of each double-double.
  State high() const;
  /// What high() leaves: value − high() per value, as a double (the trailing part).
  State low() const;

 private:
  Eigen::Index rows_ = 0;
  int cols_ = 0;
  std::vector<Extended> values_;
};

}  // namespace dlpverify
