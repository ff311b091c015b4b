#include "integrators/tableau/stability.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace dlpverify {

namespace {

using Complex = std::complex<double>;

// bᵀ (αI − βA)⁻¹ 1 by forward substitution (αI − βA is lower triangular):
// x_i = (1 + β Σ_{j<i} a_ij x_j) / (α − β a_ii). R(z) takes α = 1, β = z; bᵀA⁻¹1 takes α = 0, β = −1.
template <class T>
T weights_through(const RuntimeTableau& t, T alpha, T beta) {
  const std::size_t s = t.b.size();
  std::vector<T> x(s);
  T sum_bx = 0.0;
  for (std::size_t i = 0; i < s; ++i) {
    T sum = 0.0;
    for (std::size_t j = 0; j < i; ++j) sum += t.a[i][j] * x[j];
    x[i] = (1.0 + beta * sum) / (alpha - beta * t.a[i][i]);
    sum_bx += t.b[i] * x[i];
  }
  return sum_bx;
}

}  // namespace

// R(z) = 1 + z bᵀ (I − zA)⁻¹ 1 (stability.hpp).
Complex stability_function(const RuntimeTableau& t, Complex z) { return 1.0 + z * weights_through<Complex>(t, 1.0, z); }

std::vector<std::vector<double>> stability_grid(const RuntimeTableau& tableau, double half_width, int n) {
  std::vector<std::vector<double>> rows;
  rows.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  const double step = 2.0 * half_width / (n - 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -half_width + i * step, y = -half_width + j * step;
      rows.push_back({x, y, std::abs(stability_function(tableau, Complex(x, y)))});
    }
  return rows;
}

TableauStability tableau_stability(const RuntimeTableau& tableau) {
  TableauStability st;
  const int s = tableau.stages();
  bool invertible = true;
  st.poles_right = true;
  for (int i = 0; i < s; ++i) {
    const double d = tableau.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)];
    invertible = invertible && d != 0.0;
    st.poles_right = st.poles_right && d >= 0.0;
  }
  // A singular A (an ESDIRK's explicit first stage): R(z) = R(∞) + c₁/z + c₂/z² + …, and a far z
  // loses |z| ε to cancellation; Richardson on z₀, 2z₀, 4z₀ (z₀ = −10⁶) leaves ~1e-9.
  const auto r = [&](double z) { return stability_function(tableau, Complex(z, 0.0)).real(); };
  st.r_infinity = invertible ? std::abs(1.0 - weights_through<double>(tableau, 0.0, -1.0))
                             : std::abs((8.0 * r(-4e6) - 6.0 * r(-2e6) + r(-1e6)) / 3.0);
  st.max_on_axis = std::abs(stability_function(tableau, Complex(0.0, 0.0)));
  constexpr int kPoints = 4000;
  for (int k = 0; k < kPoints; ++k) {
    const double y = std::pow(10.0, -4.0 + 12.0 * k / (kPoints - 1));
    st.max_on_axis = std::max(st.max_on_axis, std::abs(stability_function(tableau, Complex(0.0, y))));
  }
  st.a_stable = st.poles_right && st.max_on_axis <= 1.0 + 1e-12 && st.r_infinity <= 1.0 + 1e-12;
  st.l_stable = st.a_stable && st.r_infinity <= 1e-8;
  return st;
}

}  // namespace dlpverify
