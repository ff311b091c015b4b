// The options of every problem family, as a study is given them: the case, and the values of
// each family's options (families/family.hpp declares them one by one). Unset optional values take
// the case's own.
#pragma once

#include <optional>
#include <string>

#include "problems/dlp/parameters.hpp"

namespace dlpverify::families {

// The gas cases' parcels, paths and gas (docs/model.md §7.1). Unset gas constants take the case's
// gas; --rho0 is the alternative to --molar-mass (ρ0 = M_g/v0).
struct GasOptions {
  int parcels = 400;
  double period = 1e-3;     // every parcel's path period P [s]
  double j_min_low = 0.3;   // the parcels' deepest compressions J_min spread over [low, high]
  double j_min_high = 0.9;
  double t_spread = 0.1;    // initial temperatures T0 (1 ± spread)
  std::optional<double> p_ref, t_ref, molar_mass, rho0, vdw_a, vdw_b;
  std::optional<std::string> gamma;  // monatomic | diatomic | a number > 1
};

// The thermal cases' (docs/model.md §7.3): the cooling population and its physics (unset: the
// case's), and the coupled systems' constants.
struct ThermalOptions {
  int particles = 1000;
  std::optional<double> h_c, theta_gas, theta_surroundings;
  double particle_density = 2700.0, heat_capacity = 900.0;
  double d_min = 50e-6, d_max = 200e-6;
  double emissivity_min = 0.3, emissivity_max = 0.9;
  double theta0_min = 800.0, theta0_max = 1500.0;
  double a = 2.0, b = 0.5, c = 1.0;
  int systems = 8;  // initial conditions of a coupled system
};

// The case, and the DLP cloud and physics it runs on (docs/model.md §2, §8).
struct ProblemOptions {
  std::string case_name = "drag";
  std::string shape = "sphere";
  int outer = 100;
  std::optional<int> inner;        // sphere: 1; shell: outer − 5
  std::optional<double> spacing;   // Δ; default: the particle diameter (particles touch)
  double expansion_speed = 100.0;  // u_s
  dlp::Parameters parameters;
  GasOptions gas;          // the gas cases' (docs/model.md §7.1)
  ThermalOptions thermal;  // the thermal cases' (docs/model.md §7.3)
};

}  // namespace dlpverify::families
