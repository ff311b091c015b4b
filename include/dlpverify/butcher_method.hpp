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
/// tableau files); a study asks for it with dynamic_cast and refuses extended precision without it.
class ButcherMethod {
 public:
  virtual ~ButcherMethod() = default;
  /// The method's tableau.
  virtual ButcherCoefficients butcher() const = 0;
};

/// The refusal of an integrator that steps in double only (CVODE, ARKODE, exec:, a diagonally
/// implicit tableau), named `name`, in a study in extended precision: InputError naming the "precision".
[[noreturn]] inline void refuse_double_only(const std::string& name) {
  throw InputError("precision", "extended",
                   "steps the tool's own Runge-Kutta methods and explicit tableau files; " + name + " steps in double only");
}

}  // namespace dlpverify
