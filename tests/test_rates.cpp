// The DLP right-hand side (docs/model.md §1) for one particle with the default parameters of docs/model.md §8,
// against hand computations.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/rates.hpp"

namespace unit_rates {

using namespace dlpverify;
using namespace dlpverify::dlp;
namespace tt = boost::test_tools;

namespace {
// A particle at (1, 2, 3) mm moving at (30, −40, 0) m/s (speed 50 m/s), at T_p0, with mass m0.
ParticleState particle() {
  const Parameters p;
  return {1e-3, 2e-3, 3e-3, 30.0, -40.0, 0.0, p.t_particle, p.mass0()};
}

ParticleState rates_of(const Terms& terms, const ParticleState& y) {
  Physics physics;
  physics.terms = terms;
  ParticleState dydt;
  const ParticleRates f(physics);
  f(0.0, y, dydt);
  return dydt;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(rates)

// docs/model.md §8: K = 3 ρ_a C_D / (4 ρ_p d0) = 3 · 1.2 · 0.48 / (4 · 2700 · 1e-4) = 1.728 / 1.08 = 1.6 m⁻¹.
BOOST_AUTO_TEST_CASE(drag_constant_is_1_6) {
  BOOST_TEST(Parameters{}.drag_constant() == 1.6, tt::tolerance(1e-15));
}

// Vacuum: dx/dt = v, everything else zero.
BOOST_AUTO_TEST_CASE(vacuum) {
  const ParticleState y = particle();
  const ParticleState f = rates_of(Terms{}, y);
  BOOST_TEST(f[X] == 30.0);
  BOOST_TEST(f[Y] == -40.0);
  BOOST_TEST(f[Z] == 0.0);
  for (int i = VX; i <= MASS; ++i) BOOST_TEST(f[i] == 0.0);
}

// Constant C_D: dv/dt = −K ‖v‖ v = −1.6 · 50 · (30, −40, 0) = (−2400, 3200, 0) m/s² (by hand).
BOOST_AUTO_TEST_CASE(constant_drag) {
  Terms terms;
  terms.drag = true;
  const ParticleState f = rates_of(terms, particle());
  BOOST_TEST(f[X] == 30.0);
  BOOST_TEST(f[Y] == -40.0);
  BOOST_TEST(f[VX] == -2400.0, tt::tolerance(1e-14));
  BOOST_TEST(f[VY] == 3200.0, tt::tolerance(1e-14));
  BOOST_TEST(f[VZ] == 0.0);
  BOOST_TEST(f[TEMPERATURE] == 0.0);
  BOOST_TEST(f[MASS] == 0.0);
}

// Gravity adds −9.81 m/s² on z (docs/model.md §8), on its own and on top of drag.
BOOST_AUTO_TEST_CASE(gravity) {
  Terms terms;
  terms.gravity = true;
  ParticleState f = rates_of(terms, particle());
  BOOST_TEST(f[VX] == 0.0);
  BOOST_TEST(f[VY] == 0.0);
  BOOST_TEST(f[VZ] == -9.81);
  terms.drag = true;
  f = rates_of(terms, particle());
  BOOST_TEST(f[VX] == -2400.0, tt::tolerance(1e-14));
  BOOST_TEST(f[VY] == 3200.0, tt::tolerance(1e-14));
  BOOST_TEST(f[VZ] == -9.81);
}

// docs/model.md §1: with the C_D(Re) law, C_D ‖w‖ is finite (zero) at ‖w‖ = 0: a particle at rest feels no
// drag and the rates are not NaN.
BOOST_AUTO_TEST_CASE(reynolds_law_at_rest_is_zero_not_nan) {
  Terms terms;
  terms.drag = true;
  terms.drag_law = DragLaw::reynolds;
  terms.heat = true;  // Re = 0 also enters Nu
  ParticleState y = particle();
  y[VX] = y[VY] = y[VZ] = 0.0;
  const ParticleState f = rates_of(terms, y);
  for (int i = 0; i < kFields; ++i) BOOST_TEST(std::isfinite(f[i]), "field " << i);
  BOOST_TEST(f[VX] == 0.0);
  BOOST_TEST(f[VY] == 0.0);
  BOOST_TEST(f[VZ] == 0.0);
}

// docs/model.md §1 C_D(Re) law at 50 m/s: Re = ρ_a s d / μ_a = 1.2 · 50 · 1e-4 / 1.8e-5 = 1000/3,
// C_D = 0.48 + 28 Re^−0.85, dv/dt = −(3 ρ_a / (4 ρ_p d)) C_D s v.
BOOST_AUTO_TEST_CASE(reynolds_law) {
  Terms terms;
  terms.drag = true;
  terms.drag_law = DragLaw::reynolds;
  const ParticleState f = rates_of(terms, particle());
  const double reynolds = 1000.0 / 3.0;
  const double cd = 0.48 + 28.0 * std::pow(reynolds, -0.85);
  const double factor = 3.0 * 1.2 / (4.0 * 2700.0 * 1e-4) * cd * 50.0;
  BOOST_TEST(f[VX] == -factor * 30.0, tt::tolerance(1e-13));
  BOOST_TEST(f[VY] == factor * 40.0, tt::tolerance(1e-13));
  BOOST_TEST(f[VZ] == 0.0);
}

// Heat at rest (Nu = 2): dT/dt = 12 k_a (T_a − T) / (ρ_p d² c_s) with k_a = μ_a c_p / Pr
// = 1.8e-5 · 1005 / 0.72 = 0.025125 W/(m K): 12 · 0.025125 · (300 − 1500) / (2700 · 1e-8 · 900)
// = −361.8 / 0.0243 = −14888.88… K/s (by hand).
BOOST_AUTO_TEST_CASE(heat_at_rest) {
  Terms terms;
  terms.heat = true;
  ParticleState y = particle();
  y[VX] = y[VY] = y[VZ] = 0.0;
  const ParticleState f = rates_of(terms, y);
  BOOST_TEST(Parameters{}.k_gas() == 0.025125, tt::tolerance(1e-14));
  BOOST_TEST(f[TEMPERATURE] == -361.8 / 0.0243, tt::tolerance(1e-13));
  BOOST_TEST(f[MASS] == 0.0);
  BOOST_TEST(f[VX] == 0.0);
}

// Heat with slip: Nu = 2 + 0.6 Pr^(1/3) Re^(1/2), dT/dt = 6 k_a Nu (T_a − T) / (ρ_p d² c_s)
// (Q / (m c_s) with Q = π d k_a Nu (T_a − T), m = π ρ_p d³ / 6), Re = 1000/3 at 50 m/s.
BOOST_AUTO_TEST_CASE(heat_with_slip) {
  Terms terms;
  terms.heat = true;
  const ParticleState f = rates_of(terms, particle());
  const double nusselt = 2.0 + 0.6 * std::cbrt(0.72) * std::sqrt(1000.0 / 3.0);
  const double expected = 6.0 * 0.025125 * nusselt * (300.0 - 1500.0) / (2700.0 * 1e-8 * 900.0);
  BOOST_TEST(f[TEMPERATURE] == expected, tt::tolerance(1e-13));
}

// Burning: dm/dt = −c_b d² = −10 · (1e-4)² = −1e-7 kg/s at m0; at m0/8 the diameter halves
// (d = (6 m / (π ρ_p))^(1/3)), so dm/dt = −2.5e-8 kg/s and K doubles to 3.2 m⁻¹.
BOOST_AUTO_TEST_CASE(burning) {
  Terms terms;
  terms.burning = true;
  ParticleState y = particle();
  ParticleState f = rates_of(terms, y);
  BOOST_TEST(f[MASS] == -1e-7, tt::tolerance(1e-13));
  BOOST_TEST(f[TEMPERATURE] == 0.0);

  y[MASS] /= 8.0;
  terms.drag = true;
  f = rates_of(terms, y);
  BOOST_TEST(f[MASS] == -2.5e-8, tt::tolerance(1e-13));
  BOOST_TEST(f[VX] == -3.2 * 50.0 * 30.0, tt::tolerance(1e-13));
  BOOST_TEST(f[VY] == 3.2 * 50.0 * 40.0, tt::tolerance(1e-13));
}

// Burning with the C_D(Re) law and heat: Re, C_D and Nu follow the current diameter, not d0.
// At m0/8 (by hand): d = d0/2 = 5e-5 m; at 50 m/s Re = 1.2 · 50 · 5e-5 / 1.8e-5 = 500/3;
// Re^−0.85 = e^(−0.85 (ln 500 − ln 3)) = e^(−4.3485967) = 0.01292494081, C_D = 0.48 + 28 · that
// = 0.8418983426; 3 ρ_a / (4 ρ_p d) = 3.6 / 0.54 = 20/3 m⁻¹, so dv/dt = −(20/3) · 0.8418983426 · 50 v
// = −280.6327809 v = (−8418.983426, 11225.31123, 0) m/s². Nu = 2 + 0.6 · 0.72^(1/3) · √(500/3)
// = 2 + 0.6 · 0.8962809 · 12.9099445 = 8.942562380; dT/dt = 6 k_a Nu (T_a − T) / (ρ_p d² c_s)
// = 6 · 0.025125 · 8.942562380 · (−1200) / (2700 · 2.5e-9 · 900) = −266289.6353 K/s.
// With d0 in the law or in Re instead, dv_x/dt would be −6807.76 and dT/dt −351921.7.
BOOST_AUTO_TEST_CASE(reynolds_law_and_heat_follow_the_burning_diameter) {
  Terms terms;
  terms.drag = true;
  terms.drag_law = DragLaw::reynolds;
  terms.heat = true;
  terms.burning = true;
  ParticleState y = particle();
  y[MASS] /= 8.0;
  const ParticleState f = rates_of(terms, y);
  BOOST_TEST(f[VX] == -8418.983426091616, tt::tolerance(1e-10));
  BOOST_TEST(f[VY] == 11225.311234788822, tt::tolerance(1e-10));
  BOOST_TEST(f[VZ] == 0.0);
  BOOST_TEST(f[TEMPERATURE] == -266289.63532783324, tt::tolerance(1e-10));
  BOOST_TEST(f[MASS] == -2.5e-8, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_rates
