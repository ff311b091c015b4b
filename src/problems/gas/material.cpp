// Ideal and van der Waals gas in reference-state form, docs/model.md §7.1 (seed 001).
//
// The law. van der Waals for n moles in volume V: (P + a n²/V²)(V/n − b) = R T. With the parcel's
// reference volume V0 (n moles at P0, T0) and J = V/V0, put
//   a' = a n²/V0² = a/v0²,  b' = b n/V0 = b/v0  (v0 = V0/n, the molar volume at P0, T0),
// so that  P = (R T/v0)/(J − b') − a'/J².  The reference state itself says
//   (P0 + a')(1 − b') = R T0/v0 =: P0',
// hence  P = P0' (T/T0)/(J − b') − a'/J²,  and P(1, T0) = P0'/(1 − b') − a' = P0.
// The ideal gas is a' = b' = 0: P0' = P0 and P = P0 (T/T0)/J.
//
// Internal energy and the adiabat. The van der Waals molar energy is u = c_v T − a/v (from
// (∂u/∂v)_T = T (∂P/∂T)_v − P = a/v²). Per unit mass, with v = J v0 and ρ0 = M_g/v0:
//   e(J, T) = C_v T − a'/(ρ0 J),   C_v = c_v/M_g.
// Check: (∂e/∂J)_T = a'/(ρ0 J²) = (T ∂P/∂T − P)/ρ0, as thermodynamics requires.
// A parcel of mass ρ0 V0 does work −P dV = −P V0 dJ, so per unit mass dW = −P dJ/ρ0 and, with no
// heat, de = dW:
//   C_v dT + a'/(ρ0 J²) dJ = −[P0' (T/T0)/(J − b') − a'/J²] dJ/ρ0.
// The attraction terms cancel (that is the sign check of −a'/(ρ0 J) in e), leaving
//   dT/dJ = −[P0'/(ρ0 C_v T0)] T/(J − b').
// With ρ0 = P0' M_g/(R T0), P0'/(ρ0 T0) = R/M_g, so this is the adiabat of docs/model.md §7.1,
//   dT/dJ = −(γ − 1) T/(J − b'),
// exactly when C_v = R/((γ − 1) M_g) = P0'/((γ − 1) T0 ρ0): the seed's C_v = nR/((γ − 1) ρ0 V0).
// For the ideal gas that is P0/((γ − 1) T0 ρ0); for van der Waals the P0 form would give the
// exponent (γ − 1) P0'/P0 instead, which is why NairnMPM (IdealGas.cpp) divides its ideal C_v by x.
// The ODE is linear in T with a coefficient free of T0, so a parcel that has T_init at J = 1
// follows T = T_init ((1 − b')/(J − b'))^(γ − 1), whatever T_init is.
#include "problems/gas/material.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <gsl/gsl_poly.h>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/gsl_errors.hpp"

namespace dlpverify::gas {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Errors name the physical quantity (InputError's first slot), not a command-line option.
void require_positive(const char* quantity, double value) {
  if (!std::isfinite(value) || value <= 0.0) throw InputError(quantity, value_text(value), "must be positive and finite");
}
void require_non_negative(const char* quantity, double value) {
  if (!std::isfinite(value) || value < 0.0) throw InputError(quantity, value_text(value), "must be zero or positive, and finite");
}
// P0' = (P0 + a')(1 − b') = R T0/v0  (top of this file).
double reduced_reference_pressure(double P0, double a_prime, double b_prime) { return (P0 + a_prime) * (1.0 - b_prime); }

void check_reference_state(double P0, double T0, double gamma) {
  require_positive("reference pressure P0", P0);
  require_positive("reference temperature T0", T0);
  if (!std::isfinite(gamma) || gamma <= 1.0)
    throw InputError("ratio of specific heats gamma", value_text(gamma), "must be greater than 1 and finite");
}

// The reference-state cubic. x = v0/(R T0/P0): the gas's molar volume at (P0, T0) over the ideal
// gas's. Dividing (P0 + a/v0²)(v0 − b) = R T0 by R T0/P0 gives
//   (P0 + ā/x²)(x − b̄) = P0,   ā = a/(R T0/P0)², b̄ = b/(R T0/P0),
// and multiplying by x²/P0 the monic cubic  x³ − (1 + b̄) x² + α x − α b̄ = 0,  α = ā/P0.
// The gas root is the largest real root. With f(x) the cubic, f(b̄) = −b̄² ≤ 0 and f → +∞, so for
// b̄ > 0 a root above b̄ always exists, and on the largest one P(v) falls towards 0 as v grows
// (dP/dv ≤ 0: mechanically stable). With b̄ = 0 there is none when α > 1/4: P0 then exceeds the
// highest pressure the gas can have at T0, (R T0)²/(4a). Returns NaN when no root exceeds b̄.
double gas_root(double alpha, double b_bar) {
  use_gsl_return_codes();
  double roots[3] = {kNaN, kNaN, kNaN};
  const int count = gsl_poly_solve_cubic(-(1.0 + b_bar), alpha, -alpha * b_bar, &roots[0], &roots[1], &roots[2]);
  if (count < 1) return kNaN;
  const double x = *std::max_element(roots, roots + count);  // count is 1 or 3, roots ascending
  return std::isfinite(x) && x > b_bar ? x : kNaN;
}

}  // namespace

Material::Material(double P0, double T0, double gamma, double a_prime, double b_prime, double rho0)
    : P0_(P0),
      T0_(T0),
      gamma_(gamma),
      a_prime_(a_prime),
      b_prime_(b_prime),
      P0_prime_(reduced_reference_pressure(P0, a_prime, b_prime)),
      rho0_(rho0),
      Cv_(P0_prime_ / ((gamma - 1.0) * T0 * rho0)),  // C_v = R/((γ − 1) M_g), see the top of this file
      x_(P0 / P0_prime_) {}  // x = v0/(R T0/P0) and P0' = R T0/v0

Material Material::from_reduced(const ReducedSpec& spec) {
  check_reference_state(spec.P0, spec.T0, spec.gamma);
  require_positive("reference density rho0", spec.rho0);
  require_non_negative("reduced van der Waals a'", spec.a_prime);
  if (!std::isfinite(spec.b_prime) || spec.b_prime < 0.0 || spec.b_prime >= 1.0)
    throw InputError("reduced van der Waals b'", value_text(spec.b_prime),
                     "must lie in [0, 1): the molecules cannot fill the reference volume");
  return Material(spec.P0, spec.T0, spec.gamma, spec.a_prime, spec.b_prime, spec.rho0);
}

Material Material::from_molar(const MolarSpec& spec) {
  check_reference_state(spec.P0, spec.T0, spec.gamma);
  require_positive("molar mass M_g", spec.molar_mass);
  require_non_negative("van der Waals a", spec.a);
  require_non_negative("van der Waals b", spec.b);

  const double ideal_volume = kGasConstant * spec.T0 / spec.P0;  // R T0/P0 [m³/mol]
  const double a_bar = spec.a / (ideal_volume * ideal_volume);
  const double b_bar = spec.b / ideal_volume;
  const double x = gas_root(a_bar / spec.P0, b_bar);
  if (!std::isfinite(x))
    throw InputError("van der Waals constants a, b", value_text(spec.a) + ", " + value_text(spec.b),
                     "at P0 = " + value_text(spec.P0) + " Pa, T0 = " + value_text(spec.T0) +
                         " K the reference-state cubic (P0 + a/(x V)^2)(x - b/V) = P0, V = R T0/P0, "
                         "has no gas root x > b/V");

  const double v0 = x * ideal_volume;  // the molar volume at the reference state
  const double a_prime = spec.a / (v0 * v0);
  const double b_prime = spec.b / v0;
  // ρ0 = n M_g/V0 = M_g/v0 = P0' M_g/(R T0)  (docs/model.md §7.1).
  const double rho0 = reduced_reference_pressure(spec.P0, a_prime, b_prime) * spec.molar_mass / (kGasConstant * spec.T0);
  Material gas = from_reduced({.P0 = spec.P0, .T0 = spec.T0, .rho0 = rho0, .gamma = spec.gamma,
                               .a_prime = a_prime, .b_prime = b_prime});
  gas.x_ = x;  // the cubic's root itself; P0/P0' equals it to round-off
  return gas;
}

double molar_mass_for_density(MolarSpec spec, double rho0) {
  require_positive("reference density rho0", rho0);
  spec.molar_mass = 1.0;  // any positive value: v0 does not depend on it
  const double v0 = Material::from_molar(spec).reference_volume_ratio() * kGasConstant * spec.T0 / spec.P0;
  return rho0 * v0;
}

double Material::free_volume(double J) const { return J > b_prime_ ? J - b_prime_ : kNaN; }

double Material::dP_dT(double J) const { return P0_prime_ / (T0_ * free_volume(J)); }

// P = P0' (T/T0)/(J − b') − a'/J²  (top of this file).
double Material::pressure(double J, double T) const { return dP_dT(J) * T - a_prime_ / (J * J); }

double Material::gauge_pressure(double J, double T, double ambient) const { return pressure(J, T) - ambient; }

// e = C_v T − a'/(ρ0 J)  (top of this file); NaN outside J > b' like the pressure.
double Material::internal_energy(double J, double T) const {
  if (!(J > b_prime_)) return kNaN;
  return Cv_ * T - a_prime_ / (rho0_ * J);
}

// dT/dJ = −(γ − 1) T/(J − b')  (top of this file).
double Material::adiabat_slope(double J, double T) const { return -(gamma_ - 1.0) * T / free_volume(J); }

// T = T_init ((1 − b')/(J − b'))^(γ − 1): dT/dJ above integrated from (1, T_init).
double Material::adiabat_temperature(double T_initial, double J) const {
  return T_initial * std::pow((1.0 - b_prime_) / free_volume(J), gamma_ - 1.0);
}

// Order of NairnMPM's update, and the fix.
//
// Write h = J_{n+1} − J_n (h = O(Δt) on a smooth path J(t)) and k(J) = (γ − 1)/(J − b'), so the
// adiabat is dT/dJ = −k T and ∂P/∂T = ρ0 C_v k. Over one step the exact energy balance is
//   C_v (T_{n+1} − T_n) = −(1/ρ0) ∫ P dJ − (a'/ρ0) h/(J_n J_{n+1})
// (the last term is the exact change of −a'/(ρ0 J) in e). NairnMPM takes
//   C_v (T_{n+1} − T_n) = −½ [P(J_n, T_n) + P(J_{n+1}, T_n)] h/ρ0 − (a'/ρ0) h/J_{n+1}².
// Starting from the exact T_n, its local error has three parts:
//   (i)   P at the new end uses T_n for T_{n+1}: −½ ∂P/∂T (T_n − T_{n+1}) h/ρ0 in C_v ΔT, and
//         T_{n+1} − T_n = −k T h + O(h²), so  δT = −½ k² T h² + O(h³);
//   (ii)  the trapezoid's own error, −(h³/12) P''/ρ0: O(h³);
//   (iii) the attraction energy: h/J_{n+1}² − h/(J_n J_{n+1}) = −h²/(J_n J_{n+1}²), so
//         δT = +a' h²/(ρ0 C_v J³) + O(h³)  (zero for the ideal gas).
// The local error is O(h²) = O(Δt²); over the O(1/Δt) steps of a fixed path it adds up to a global
// error ≈ Δt ∫ [−½ k² T + a'/(ρ0 C_v J³)] J'(t)² dt, each step's error carried to the end by the
// adiabat's own growth factor: first order. h² ≥ 0, so compression and expansion err the same way and no path cancels it.
// For the ideal gas (i) is the only first-order term; for van der Waals (iii) is a second one.
//
// The fix makes both ends of the trapezoid use their own temperature and takes the attraction
// energy as the exact difference of e:
//   e(J_{n+1}, T_{n+1}) − e(J_n, T_n) = −½ [P(J_n, T_n) + P(J_{n+1}, T_{n+1})] h/ρ0,
// the trapezoidal rule for de = −P dJ/ρ0, whose local error is (ii) alone: second order. P is
// linear in T, P = β(J) T − a'/J² with β = ∂P/∂T, so the implicit end is solved exactly:
//   T_{n+1} = [e(J_n, T_n) + a'/(ρ0 J_{n+1}) − ½ (P(J_n, T_n) − a'/J_{n+1}²) h/ρ0]
//             / [C_v + ½ β(J_{n+1}) h/ρ0],
// with denominator C_v (1 + ½ k(J_{n+1}) h) > 0 unless a single compression step has
// h ≤ −2 (J_{n+1} − b')/(γ − 1). The rule is symmetric: stepping back through the same J values
// returns T_n to round-off, so an out-and-back path measures nothing; measure at, e.g., the
// deepest compression.
double nairn_temperature_step(const Material& gas, double J_n, double T_n, double J_next) {
  const double h = J_next - J_n;
  const double work = -0.5 * (gas.pressure(J_n, T_n) + gas.pressure(J_next, T_n)) * h / gas.rho0();
  return T_n + (work - gas.a_prime() / gas.rho0() * h / (J_next * J_next)) / gas.Cv();
}

double trapezoid_temperature_step(const Material& gas, double J_n, double T_n, double J_next) {
  const double h = J_next - J_n;
  const double denominator = gas.Cv() + 0.5 * gas.dP_dT(J_next) * h / gas.rho0();
  if (!(denominator > 0.0)) return kNaN;
  const double attraction_next = gas.a_prime() / (J_next * J_next);  // a'/J_{n+1}²
  const double numerator = gas.internal_energy(J_n, T_n) + gas.a_prime() / (gas.rho0() * J_next) -
                           0.5 * (gas.pressure(J_n, T_n) - attraction_next) * h / gas.rho0();
  return numerator / denominator;
}

}  // namespace dlpverify::gas
