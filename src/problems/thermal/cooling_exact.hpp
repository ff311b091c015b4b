// Closed forms of lumped particle cooling (docs/model.md §7.3),
//   dθ/dt = −α (θ − θ_o) − β (θ⁴ − θ_s⁴),   α = h_c a_s/(m C),  β = ε σ a_s/(m C),
// in the three cases where one exists.
#pragma once

namespace dlpverify::thermal {

// Radiation only (α = 0) into surroundings at θ_s > 0: θ(t) from
//   β t = F(θ0) − F(θ),  F(θ) = ln|(θ − θ_s)/(θ + θ_s)|/(4 θ_s³) − atan(θ/θ_s)/(2 θ_s³),
// by a bracketing root solve (GSL's Brent) between θ0 and θ_s.
double radiation_to_surroundings(double theta0, double beta, double theta_s, double t);

// Radiation only into θ_s = 0: θ = θ0 (1 + 3 β θ0³ t)^(−1/3).
double radiation_to_vacuum(double theta0, double beta, double t);

// Convection and radiation into θ_o = θ_s = 0, a Bernoulli equation (u = θ⁻³ is linear):
//   θ = [(θ0⁻³ + β/α) e^(3αt) − β/α]^(−1/3).
double convection_and_radiation_to_zero(double theta0, double alpha, double beta, double t);

}  // namespace dlpverify::thermal
