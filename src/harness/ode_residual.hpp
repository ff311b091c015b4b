// ODE residual of a closed form (docs/model.md §4, last paragraph: "its time derivative, by a
// high-order finite difference, must satisfy the ODE"), for any problem.
//
// For the closed form y(τ) of a problem with right-hand side f:
//
//   D_h y(τ) = Σ_{k=1..4} c_k [y(τ + k h) − y(τ − k h)] / h,
//              c = (4/5, −1/5, 4/105, −1/280)                  (8th-order central difference)
//            = y'(τ) − (h⁸/630) y⁽⁹⁾(τ) + O(h¹⁰)
//
//   residual_g = ‖D_h y_g(τ) − f_g(t, y(τ))‖ / max(‖f_g(t, y(τ))‖, ‖y_g(τ)‖ / T, DBL_MIN)
//
// for each field group g of each member (the problem's variables, then any field outside them),
// ‖·‖ the Euclidean norm over the group's fields. T is the member's time scale
// (Problem::time_scale), so ‖y_g‖ / T is the rate at which the group would change on that scale:
// it keeps the residual relative where the group's own rate is zero or nearly so (a particle at
// rest), where dividing by ‖f_g‖ would turn round-off into an arbitrarily large number. Each
// member's optimal step is h = T/100 (or down to T/1000 for small τ > 0, see ode_residual.cpp);
// members whose steps lie within a factor 8 share the smallest of them, so no member's truncation
// error exceeds its optimum and none is differenced at a step so small that round-off rules.
//
// A correct closed form gives ~1e-13; a wrong one, a residual of order one. A member whose kink
// (Problem::kink_times) lies within the stencil [τ − 4h, τ + 4h] is skipped: there the solution
// is only once differentiable and the difference measures the kink, not the formula.
#pragma once

#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

struct OdeResidual {
  std::vector<double> groups;  // the largest finite relative residual of each field group over the members
  double step = 0.0;           // the smallest finite-difference step h used [s]
  double time_scale = 0.0;     // the smallest member time scale T [s]
  int skipped = 0;             // members whose kink lay inside the stencil
  int non_finite = 0;          // member residuals that were NaN or infinite (a closed form that fails)

  // The largest finite residual over the groups.
  double max() const;
};

OdeResidual ode_residual(const Problem& problem, const State& initial, double tau);

}  // namespace dlpverify
