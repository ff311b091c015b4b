/// @file
/// An integrator that is a Runge–Kutta method given by its Butcher tableau says so: its
/// coefficients are what a study in extended precision steps with (dlpverify/extended_study.hpp),
/// since the integrator's own advance() is double only.
#pragma once

#include <string>
#include <vector>

#include "dlpverify/errors.hpp"

namespace dlpverify {

/// A Butcher tableau's coefficients as the integrator holds them (doubles).
struct ButcherCoefficients {
  std::vector<std::vector<double>> a;  ///< a[i][j], s × s, zero above the diagonal
  std::vector<double> b;               ///< weights b_i
  std::vector<double> c;               ///< nodes c_i
  int stages() const { return static_cast<int>(b.size()); }  ///< s
};

/// Implemented by the integrators that are a Butcher tableau (the built-in Runge–Kutta methods,
/// explicit tableau files, ARKODE's explicit tables); a study asks for it with dynamic_cast and
/// refuses extended precision without it.
class ButcherMethod {
 public:
  virtual ~ButcherMethod() = default;
  /// The method's tableau.
  virtual ButcherCoefficients butcher() const = 0;
  /// Whether butcher() has an explicit tableau to give: false for a wrapper of a method that
  /// steps in double only, whose butcher() refuses.
  virtual bool has_explicit_tableau() const { return true; }
};

/// Why an integrator named `name` that steps in double only (CVODE, ARKODE's adaptive and implicit
/// methods, exec:, a diagonally implicit tableau) cannot run in extended precision.
inline std::string double_only(const std::string& name) {
  return "steps the explicit Runge-Kutta methods whose tableau it reads (built-in, tableau files, arkode-erk:TABLE); " +
         name + " steps in double only";
}

/// The refusal of such an integrator in a study in extended precision: InputError naming the "precision".
[[noreturn]] inline void refuse_double_only(const std::string& name) {
  throw InputError("precision", "extended", double_only(name));
}

}  // namespace dlpverify
