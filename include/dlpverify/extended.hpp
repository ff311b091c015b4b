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

#include "dlpverify/precision.hpp"
#include "dlpverify/problem.hpp"

/// ∛a in double-double (QD's nroot), beside QD's sqrt and pow: a formula written once for a Real
/// type (`using std::cbrt; cbrt(x)`) finds it by argument lookup.
inline dd_real cbrt(const dd_real& a) { return nroot(a, 3); }

namespace dlpverify {

/// The extended arithmetic: QD's double-double (about 32 significant digits).
using Extended = dd_real;

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

/// A capability (problem.hpp): the problem's right-hand side evaluated in Extended, the same
/// ODE as Problem::rhs with every operation in double-double (its constants are the double
/// problem's, so both arithmetics solve one ODE). A study in extended precision needs it
/// (dlpverify/extended_study.hpp); without it the problem runs in double only.
class ExtendedRhs : public Capability {
 public:
  /// dy/dt = f(t, y) of the members first … first + count − 1, as Problem::rhs: field f of the
  /// block's member i is y[f][i]. Called concurrently from several threads on disjoint blocks.
  virtual void extended_rhs(const Extended& t, Eigen::Index first, int count, const Extended* const* y,
                   Extended* const* dydt) const = 0;
};

}  // namespace dlpverify
