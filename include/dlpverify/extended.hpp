/// @file
/// Studies in extended precision (docs/verification.md, "Extended precision"): a problem that can
/// evaluate its right-hand side in Extended arithmetic (the ExtendedRhs capability) is stepped by
/// an integrator the tool owns in that arithmetic (ExtendedSteps), compared with a reference in the
/// same arithmetic (the ExtendedClosedForm capability, a manufactured solution, or an integrator
/// reference), and the differences are taken in Extended before they are reported as doubles.
/// Double precision's round-off floor, ½ ε √n ‖y‖ with ε = 2^−52, then moves to ε = 2^−104: a
/// fifth- or eighth-order method's asymptotic range, empty in double, opens.
///
/// Extended is QD's double-double (Debian's libqd-dev): a value is an unevaluated sum of two
/// doubles, 106 bits of significand, about 32 significant digits. Measured against __float128
/// through Boost.Multiprecision on the DLP cloud's right-hand side it is six times as fast
/// (docs/performance.md); its elementary functions (sqrt, nroot, exp, log, pow, sin, cos, …) are
/// accurate to a few units of its last place. It needs IEEE double arithmetic without fused
/// contractions the source did not write, which the project's flags keep (-ffp-contract=off, never
/// -ffast-math).
///
/// A problem offers the capability by writing its equations once, as a template over the scalar,
/// and instantiating it for double (Problem::rhs) and for Extended (ExtendedRhs::rhs):
/// @code
///   class Decay : public dlpverify::Problem, public dlpverify::ExtendedRhs {
///     template <class T> void f(const T& t, int count, const T* const* y, T* const* dydt) const {
///       for (int i = 0; i < count; ++i) dydt[0][i] = -y[0][i];
///     }
///    public:
///     Decay() { provide<dlpverify::ExtendedRhs>(*this); }
///     void rhs(double t, Eigen::Index, int n, const double* const* y, double* const* d) const override { f(t, n, y, d); }
///     void rhs(const dlpverify::Extended& t, Eigen::Index, int n, const dlpverify::Extended* const* y,
///              dlpverify::Extended* const* d) const override { f(t, n, y, d); }
///     …
///   };
/// @endcode
#pragma once

#include <string>
#include <vector>

#include <qd/dd_real.h>

#include "dlpverify/problem.hpp"
#include "dlpverify/solver_statistics.hpp"

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

/// A capability (problem.hpp): the problem's own right-hand side in Extended, the same equations as
/// Problem::rhs to the last digit of double (a study in extended precision compares the two on the
/// initial state and refuses a problem whose two differ by more than rounding).
class ExtendedRhs : public Capability {
 public:
  /// dy/dt = f(t, y) of the members first … first + count − 1, as Problem::rhs, in Extended.
  /// Called concurrently from several threads on disjoint blocks.
  virtual void rhs(const Extended& t, Eigen::Index first, int count, const Extended* const* y,
                   Extended* const* dydt) const = 0;
  /// The measured columns at t0 + tau of members first … (Problem::measured) in Extended: the
  /// fields themselves by default. A problem whose measured columns derive quantities from its
  /// fields (a pressure) gives them here too.
  virtual ExtendedState measured(ExtendedState state, double /*tau*/, Eigen::Index /*first*/ = 0) const { return state; }
};

/// A capability (problem.hpp): the problem's closed form (ClosedForm) in Extended.
class ExtendedClosedForm : public Capability {
 public:
  /// The state at t0 + tau of members first … first + initial.rows() − 1 whose state at t0 is
  /// `initial` (the launch state, doubles), in Extended.
  virtual ExtendedState solution(Eigen::Index first, const State& initial, double tau) const = 0;
};

/// What an integrator the tool owns offers (Integrator::extended): its steps in Extended.
class ExtendedSteps {
 public:
  virtual ~ExtendedSteps() = default;
  /// Advances every member of `state` from t0 by `steps` steps of Δt = duration / steps, both
  /// taken in Extended (step n starts at t0 + n Δt), evaluating `rhs` (the problem's ExtendedRhs,
  /// or a wrapper's); `problem` is the same problem, for its other capabilities.
  virtual void advance_extended(const Problem& problem, const ExtendedRhs& rhs, ExtendedState& state, double t0,
                                double duration, long steps) = 0;
  /// Solver statistics of the last advance_extended (Integrator::statistics' counts).
  virtual SolverStatistics extended_statistics() const { return {}; }
};

/// evaluate the right-hand side in Extended over a whole population, in blocks of members shared
/// over OpenMP threads (evaluate_rhs's blocks): `rates` receives f(t, state).
void evaluate_extended_rhs(const ExtendedRhs& rhs, const Extended& t, const ExtendedState& state, ExtendedState& rates);

}  // namespace dlpverify
