// Ideal and van der Waals gas in reference-state form (docs/model.md §7.1, seed 001), and
// NairnMPM's per-step adiabatic temperature update with a second-order variant of it.
//
// Everything is per unit reference volume or per unit mass of one gas parcel (a material point):
// J = V/V0 is the parcel's volume ratio, T its temperature. SI units throughout: Pa, K, kg/m³,
// J/(kg K), kg/mol, m³/mol.
//
// An ideal gas is the van der Waals gas with a' = b' = 0: every formula below reduces to the ideal
// one exactly (P0' = P0, J − b' = J, a'/J² = 0 in floating point too), so there is one code path.
//
// Domain: the laws hold for J > b' (the molecules' own volume cannot be compressed). The per-parcel
// functions are evaluated inside integrator loops, so outside that domain they return NaN instead
// of throwing; the harness treats a non-finite value as a failed level. The factories validate
// their input and throw InputError naming the physical quantity.
#pragma once

namespace dlpverify::gas {

inline constexpr double kGasConstant = 8.314462618;   // R [J/(mol K)], exact since the 2019 SI
inline constexpr double kOneAtmosphere = 101325.0;    // [Pa]
inline constexpr double kGammaMonatomic = 5.0 / 3.0;  // γ = c_p/c_v of a monatomic gas
inline constexpr double kGammaDiatomic = 7.0 / 5.0;   // γ of a diatomic gas (air)

// A gas from its molar constants. a = b = 0 is the ideal gas.
struct MolarSpec {
  double P0 = kOneAtmosphere;    // reference pressure [Pa]
  double T0 = 300.0;             // reference temperature [K]
  double molar_mass = 0.0;       // M_g [kg/mol]; required (air: 0.02897)
  double gamma = kGammaDiatomic;
  double a = 0.0;                // van der Waals a [Pa m⁶/mol²]
  double b = 0.0;                // van der Waals b [m³/mol]
};

// A gas already in reference-state form: the density ρ0 (an input in NairnMPM too) and the reduced
// constants a', b' given directly. a' = b' = 0 is the ideal gas.
struct ReducedSpec {
  double P0 = kOneAtmosphere;    // reference pressure [Pa]
  double T0 = 300.0;             // reference temperature [K]
  double rho0 = 0.0;             // reference density [kg/m³]
  double gamma = kGammaDiatomic;
  double a_prime = 0.0;          // a' [Pa]
  double b_prime = 0.0;          // b' (fraction of the reference volume the molecules occupy)
};

// The molar mass that gives `spec`'s gas the reference density rho0: ρ0 = M_g/v0, with the molar
// volume v0 from the reference-state cubic (which does not involve M_g). For a study that knows
// ρ0 rather than M_g. Throws InputError like from_molar, or for a non-positive rho0.
double molar_mass_for_density(MolarSpec spec, double rho0);

class Material {
 public:
  // Solve the reference-state cubic for x and build a', b', P0', ρ0. Throws InputError for
  // non-positive P0, T0 or M_g, γ ≤ 1, negative a or b, or no gas root of the cubic.
  static Material from_molar(const MolarSpec& spec);
  // Throws InputError for non-positive P0, T0 or ρ0, γ ≤ 1, a' < 0, or b' outside [0, 1).
  static Material from_reduced(const ReducedSpec& spec);

  bool is_van_der_waals() const { return a_prime_ > 0.0 || b_prime_ > 0.0; }

  double P0() const { return P0_; }              // reference pressure [Pa]
  double T0() const { return T0_; }              // reference temperature [K]
  double gamma() const { return gamma_; }
  double a_prime() const { return a_prime_; }    // a' [Pa]
  double b_prime() const { return b_prime_; }    // b'
  double P0_prime() const { return P0_prime_; }  // P0' = (P0 + a')(1 − b') [Pa]
  double rho0() const { return rho0_; }          // ρ0 [kg/m³]
  double Cv() const { return Cv_; }              // specific heat at constant volume [J/(kg K)]
  // x: the gas's molar volume at (P0, T0) over the ideal gas's, R T0/P0 (1 for an ideal gas).
  double reference_volume_ratio() const { return x_; }

  // Absolute pressure P(J, T) [Pa].
  double pressure(double J, double T) const;
  // Gauge pressure P(J, T) − P_ref against an ambient P_ref [Pa]. The seed's gauge mode has
  // P0 = P_ref = 1 atm, so the gauge pressure of the reference state is zero.
  double gauge_pressure(double J, double T, double ambient) const;
  // Specific internal energy e(J, T) = C_v T − a'/(ρ0 J) [J/kg], up to a constant.
  double internal_energy(double J, double T) const;
  // dT/dJ on an adiabat through (J, T) [K].
  double adiabat_slope(double J, double T) const;
  // Temperature at J on the adiabat of a parcel that had temperature T_initial at J = 1.
  double adiabat_temperature(double T_initial, double J) const;
  // ∂P/∂T at fixed J [Pa/K]: P is linear in T, P = dP_dT(J) T − a'/J².
  double dP_dT(double J) const;

 private:
  Material(double P0, double T0, double gamma, double a_prime, double b_prime, double rho0);
  double free_volume(double J) const;  // J − b', or NaN outside the domain J > b'

  double P0_, T0_, gamma_, a_prime_, b_prime_, P0_prime_, rho0_, Cv_, x_;
};

// NairnMPM's adiabatic update for one step of a parcel from (J_n, T_n) to J_next, as published:
// both ends of the trapezoidal work at T_n, and the attraction energy as a'ΔJ/(J_next)². First
// order in the step (see material.cpp). Returns T_{n+1}, or NaN outside the domain.
double nairn_temperature_step(const Material& gas, double J_n, double T_n, double J_next);

// The same update made second order: the trapezoidal work with the end pressure at T_{n+1}
// (solved exactly: P is linear in T) and the attraction energy as the exact difference of e.
// Returns T_{n+1}, or NaN outside the domain or for a compression step too large to solve.
double trapezoid_temperature_step(const Material& gas, double J_n, double T_n, double J_next);

}  // namespace dlpverify::gas
