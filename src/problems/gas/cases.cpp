#include "problems/gas/cases.hpp"

namespace dlpverify::gas {

namespace {
// With the default paths (period P = 1 ms, J_min from 0.3 to 0.9): t_end = ¾ P takes every parcel
// through its deepest compression and half-way back, so compression and expansion both count and
// the end is not a turning point. The coarsest Δt = P/80 gives 60 steps (at P/40 RK2's first
// level is still pre-asymptotic: fitted order 2.11); 5 levels reach 960 steps, where RK4's error
// (1e-9 K) is still far above round-off.
constexpr StudyDefaults kPathStudy{7.5e-4, 1.25e-5, 5};
}  // namespace

const std::vector<GasCase>& all_gas_cases() {
  static const std::vector<GasCase> cases{
      {"adiabat-ideal", "gas parcels compressed and released adiabatically, ideal gas (air, 1 atm, 300 K)",
       "air: M = 28.97 g/mol, gamma = 7/5",
       MolarSpec{.P0 = kOneAtmosphere, .T0 = 300.0, .molar_mass = 0.02897, .gamma = kGammaDiatomic}, kPathStudy},
      // CO2's van der Waals constants; at 20 bar the reference molar volume is 9 % below the ideal
      // gas's (x = 0.911) and a' = 0.141 P0, b' = 0.0376, so both corrections matter.
      // gamma = 1.29: CO2's c_p/c_v near 300 K (linear triatomic; neither 5/3 nor 7/5).
      {"adiabat-vdw", "gas parcels compressed and released adiabatically, van der Waals gas (CO2, 20 bar, 300 K)",
       "CO2: M = 44.01 g/mol, a = 0.3640 Pa m^6/mol^2, b = 4.267e-5 m^3/mol, gamma = 1.29",
       MolarSpec{.P0 = 2.0e6, .T0 = 300.0, .molar_mass = 0.04401, .gamma = 1.29, .a = 0.3640, .b = 4.267e-5}, kPathStudy},
  };
  return cases;
}

const GasCase* find_gas_case(const std::string& name) {
  for (const GasCase& c : all_gas_cases())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace dlpverify::gas
