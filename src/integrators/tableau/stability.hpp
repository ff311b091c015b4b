// The linear stability of a diagonally implicit Runge–Kutta tableau (Hairer & Wanner, Solving
// ODEs II, §IV.3): on y' = λy a step multiplies y by
//
//   R(z) = 1 + z bᵀ (I − zA)⁻¹ 1,   z = λΔt.
//
// A-stable: |R(z)| ≤ 1 on Re z ≤ 0. A DIRK's poles are z = 1/a_ii, all in the right half-plane when
// every a_ii ≥ 0 (a zero diagonal entry adds none); R is then analytic on Re z ≤ 0 and, by the
// maximum principle, A-stable iff |R(iy)| ≤ 1 on the imaginary axis and |R(∞)| ≤ 1. L-stable:
// A-stable and R(∞) = 0. The axis is sampled (R(−iy) is the conjugate of R(iy): y > 0 suffices).
#pragma once

#include <complex>
#include <vector>

#include "integrators/tableau/tableau_file.hpp"

namespace dlpverify {

struct TableauStability {
  double r_infinity = 0.0;      // |R(∞)|: |1 − bᵀA⁻¹1| when A is invertible, else extrapolated (~1e-9)
  double max_on_axis = 0.0;     // the largest |R(iy)| over the sampled axis
  bool poles_right = false;     // every a_ii ≥ 0: no pole in the left half-plane
  bool a_stable = false;        // poles_right, max_on_axis ≤ 1 and r_infinity ≤ 1 (to 1e-12)
  bool l_stable = false;        // a_stable and r_infinity ≤ 1e-8
};

// The stability of `tableau` (a diagonally implicit one: an explicit R is a polynomial, never
// A-stable). The axis is sampled at y = 0 and 4,000 points log-spaced over [1e-4, 1e8].
TableauStability tableau_stability(const RuntimeTableau& tableau);

// R(z) of `tableau` (explicit or diagonally implicit), by forward substitution through I − zA.
std::complex<double> stability_function(const RuntimeTableau& tableau, std::complex<double> z);

// |R(z)| on an n × n grid over Re z, Im z ∈ [−half_width, half_width]: rows (Re z, Im z, |R|),
// Re z varying fastest (a stability region's figure).
std::vector<std::vector<double>> stability_grid(const RuntimeTableau& tableau, double half_width, int n);

}  // namespace dlpverify
