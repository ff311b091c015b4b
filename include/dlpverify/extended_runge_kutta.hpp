/// @file
/// An explicit Runge–Kutta method stepped in Extended (dlpverify/extended.hpp):
///
/// @code{.unparsed}
///   k_i = f(t + c_i Δt, y + Δt Σ_{j<i} a_ij k_j),   y_{n+1} = y_n + Δt Σ_i b_i k_i
/// @endcode
///
/// every operation in double-double, through the problem's ExtendedRhs. The coefficients an
/// integrator holds are doubles: 1/3 is 0.333…3 to 16 digits, and a method stepped with it misses
/// its order conditions by 1e-17, a floor no arithmetic removes. Each coefficient is therefore
/// read as the simplest fraction whose nearest double it is (exact_coefficient): every tableau the
/// project ships and the literature prints has rational coefficients of small denominators; one
/// that has no such fraction is taken as the double it is. Written by hand: SUNDIALS and
/// Boost.Odeint step in double (odeint's steppers would take dd_real, but not a block of members
/// through the problem's block right-hand side).
#pragma once

#include <vector>

#include "dlpverify/butcher_method.hpp"
#include "dlpverify/extended.hpp"

namespace dlpverify {

/// The fraction p/q with the smallest q ≤ 2^24 whose nearest double is `x`, in Extended (its
/// continued fraction's first convergent that rounds to x); `x` itself when there is none.
Extended exact_coefficient(double x);

/// Whether every coefficient of `tableau` is such a fraction: otherwise the method stepped in
/// Extended misses its order conditions by about 1e-17, an error floor near 1e-16 ‖y‖ that the
/// round-off rules of Extended (ε = 2^−104) do not model, so a check does not escalate it.
bool read_exactly(const ButcherCoefficients& tableau);

/// An explicit tableau in Extended, its coefficients read by exact_coefficient.
class ExtendedRungeKutta {
 public:
  /// Refuses a tableau with a nonzero a_ij on or above the diagonal (InputError naming the
  /// "precision": a diagonally implicit method is not stepped in extended precision).
  explicit ExtendedRungeKutta(const ButcherCoefficients& tableau);
  /// Advances every member of `state` from t0 by `steps` steps of dt (step n at t0 + n·dt), block
  /// by block, one OpenMP thread a block. The problem must offer ExtendedRhs (InputError naming
  /// the "precision" otherwise).
  void advance(const Problem& problem, ExtendedState& state, const Extended& t0, const Extended& dt, long steps) const;
  int stages() const { return static_cast<int>(b_.size()); }  ///< s

 private:
  std::vector<std::vector<Extended>> a_;
  std::vector<Extended> b_, c_;
};

}  // namespace dlpverify
