// The cloud's kinetic energy, an invariant of the vacuum expansion (docs/model.md §2).
//
//   KE = Σ_p ½ m_p ‖v_p‖²
//
// For a continuous uniform sphere of mass M launched with the similarity velocity u = ξ u_s,
// KE = ∫ ½ ρ u² dV = 0.3 M u_s² (the seed's eqs. 10–11). The lattice has KE / (0.3 N m u_s²)
// = Σ ξ² / (0.6 N) (each particle has mass m and speed ξ u_s), which tends to 1 as the lattice
// refines: 0.997337 at R_out = 10, 0.999627 at 50, 0.999852 at 100 (docs/model.md §2).
#pragma once

#include "problems/dlp/cloud.hpp"

namespace dlpverify::dlp {

// ½ m_p ‖v_p‖² of particle p of `state`.
double particle_kinetic_energy(const CloudArray& state, Eigen::Index p);

double kinetic_energy(const Cloud& cloud);

// KE / (0.3 M u_s²): the lattice's kinetic energy against the continuous sphere's of mass M.
double similarity_energy_ratio(double kinetic_energy, double total_mass, const Launch& launch);
// The same with M = Σ m_p of `cloud`.
double similarity_energy_ratio(const Cloud& cloud, const Launch& launch);

}  // namespace dlpverify::dlp
