#include "problems/thermal/cases.hpp"

namespace dlpverify::thermal {

namespace {
// With the default population (50–200 µm, ε 0.3–0.9, θ0 800–1500 K) the fastest rate α + 4βθ³ is
// about 40/s: over 0.5 s every particle cools by hundreds of kelvin, and the coarsest Δt = 0.01 s
// (Δt × rate ≈ 0.4) is inside RK2's asymptotic range and the fixed point's convergence.
constexpr StudyDefaults kCooling{0.5, 0.01, 5};
// The coupled systems converge for Δt < 1: Δt = 0.05 … 0.003 over one time unit.
constexpr StudyDefaults kCoupled{1.0, 0.05, 5};

CoolingPhysics physics(double h_c, double theta_gas, double theta_surroundings) {
  CoolingPhysics p;
  p.h_c = h_c;
  p.theta_gas = theta_gas;
  p.theta_surroundings = theta_surroundings;
  return p;
}
}  // namespace

const std::vector<ThermalCase>& all_thermal_cases() {
  static const std::vector<ThermalCase> cases{
      {"cooling", "hot particles cooling by convection and radiation into warm gas and surroundings (300 K)",
       "convection h_c = 100 W/(m^2 K), radiation", 0, physics(100.0, 300.0, 300.0), kCooling},
      {"cooling-radiation", "hot particles cooling by radiation alone into surroundings at 300 K",
       "radiation (h_c = 0)", 0, physics(0.0, 300.0, 300.0), kCooling},
      {"cooling-radiation-vacuum", "hot particles cooling by radiation alone into surroundings at 0 K",
       "radiation (h_c = 0, theta_s = 0)", 0, physics(0.0, 0.0, 0.0), kCooling},
      {"cooling-bernoulli", "hot particles cooling by convection and radiation into gas and surroundings at 0 K",
       "convection h_c = 100 W/(m^2 K), radiation, theta_o = theta_s = 0", 0, physics(100.0, 0.0, 0.0), kCooling},
      {"stagger-2x2", "Zohdi's coupled pair a w1' + w2 = 0, b w2' + w1 = 0 (staggering converges for dt < sqrt(ab))",
       "linear coupling, a = 2, b = 0.5", 2, {}, kCoupled},
      {"stagger-3x3", "Zohdi's coupled triple a w1' + w2 = 0, b w2' + w3 = 0, c w3'' + w1 = 0 (dt < |abc|^(1/4))",
       "linear coupling, a = 2, b = 0.5, c = 1", 3, {}, kCoupled},
  };
  return cases;
}

const ThermalCase* find_thermal_case(const std::string& name) {
  for (const ThermalCase& c : all_thermal_cases())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace dlpverify::thermal
