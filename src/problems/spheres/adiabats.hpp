// The laws a compression is measured against (docs/model.md §7.2). r is the volume ratio V1/V2.
//   ideal gas, monatomic:                 T2/T1 = r^(2/3)
//   one axis compressed, no collisions:   T2/T1 = (r² + 2)/3   (T_x ∝ L⁻², the other axes keep theirs)
//   hard-sphere fluid (Carnahan–Starling): d ln T = −(2/3) Z(η) d ln V,
//                                          Z(η) = (1 + η + η² − η³)/(1 − η)³
#pragma once

namespace dlpverify::compress {

double ideal_adiabat(double volume_ratio);
double collisionless_one_axis(double length_ratio);
double carnahan_starling_z(double packing);

// T2/T1 along the Carnahan–Starling adiabat from packing fraction η1, integrated with GSL's
// odeiv2 (Runge–Kutta–Prince–Dormand 8(9), relative tolerance 1e-12) in x = ln(V1/V):
// d ln T/dx = (2/3) Z(η1 eˣ). Throws InputError unless 0 ≤ η1 and η1 r < 1, SolverError if GSL fails.
double carnahan_starling_adiabat(double packing1, double volume_ratio);

// The same in closed form, for checking the integration: Z − 1 = η d/dη [(4η − 3η²)/(1 − η)²]
// (the Carnahan–Starling excess free energy), so ln(T2/T1) = (2/3)[ln(η2/η1) + f(η2) − f(η1)].
double carnahan_starling_adiabat_closed_form(double packing1, double volume_ratio);

}  // namespace dlpverify::compress
