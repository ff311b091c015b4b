// Physical parameters of the DLP model and which of its terms are switched on.
// Defaults are docs/model.md §8: a 100 µm aluminium-like particle cloud in air.
#pragma once

#include <array>
#include <numbers>

namespace dlpverify::dlp {

struct Parameters {
  double diameter = 1e-4;          // d0, initial particle diameter [m]
  double rho_particle = 2700.0;    // ρ_p [kg/m³]
  double cs_particle = 900.0;      // c_s, particle specific heat [J/(kg K)]
  double t_particle = 1500.0;      // T_p0, initial particle temperature [K]
  double rho_gas = 1.2;            // ρ_a [kg/m³]
  double mu_gas = 1.8e-5;          // μ_a [Pa s]
  double cp_gas = 1005.0;          // c_p of the gas [J/(kg K)]
  double prandtl = 0.72;           // Pr
  double t_gas = 300.0;            // T_a [K]
  double cd = 0.48;                // constant drag coefficient C_D
  double gravity = 9.81;           // ‖g‖ [m/s²]; g = (0, 0, −gravity) when on
  double burn_rate = 10.0;         // c_b in ṡ = c_b d² [kg/(m² s)]

  // Gas conductivity k_a = μ_a c_p / Pr (docs/model.md §1; seed eq. 18 misprints it, docs/model.md §9).
  double k_gas() const { return mu_gas * cp_gas / prandtl; }
  // Initial particle mass m0 = π ρ_p d0³ / 6.
  double mass0() const { return std::numbers::pi * rho_particle * diameter * diameter * diameter / 6.0; }
  // The drag prefactor of docs/model.md §1, dv/dt = (3 ρ_a / (4 ρ_p d)) C_D ‖w‖ w + g, in the three
  // groupings the model uses (each evaluated in its own order, so every result is reproducible):
  //   3 ρ_a / (4 ρ_p)            with C_D(Re) and d left to the caller (the right-hand side)
  //   κ = 3 ρ_a C_D / (4 ρ_p)    constant C_D, d left to the caller (burning, §4.6: K = κ/d)
  //   K = 3 ρ_a C_D / (4 ρ_p d0) constant C_D at the initial diameter (§4.3–4.5)
  double drag_prefactor() const { return 3.0 * rho_gas / (4.0 * rho_particle); }
  double drag_kappa() const { return 3.0 * rho_gas * cd / (4.0 * rho_particle); }
  double drag_constant() const { return 3.0 * rho_gas * cd / (4.0 * rho_particle * diameter); }
};

enum class DragLaw { constant, reynolds };  // constant C_D, or C_D(Re) = 0.48 + 28 Re^−0.85

// Which terms of docs/model.md §1 are active. The gas is quiescent (u = 0) throughout (docs/model.md §4).
struct Terms {
  bool drag = false;
  DragLaw drag_law = DragLaw::constant;
  bool gravity = false;
  bool heat = false;
  bool burning = false;
};

struct Physics {
  Parameters parameters;
  Terms terms;
};

}  // namespace dlpverify::dlp
