#include "problems/dlp/kinetic_energy.hpp"

namespace dlpverify::dlp {

double particle_kinetic_energy(const CloudArray& state, Eigen::Index p) {
  const double vx = state(p, VX), vy = state(p, VY), vz = state(p, VZ);
  return 0.5 * state(p, MASS) * (vx * vx + vy * vy + vz * vz);
}

double kinetic_energy(const Cloud& cloud) {
  double sum = 0.0;
  for (Eigen::Index p = 0; p < cloud.size(); ++p) sum += particle_kinetic_energy(cloud.state(), p);
  return sum;
}

double similarity_energy_ratio(double kinetic_energy, double total_mass, const Launch& launch) {
  return kinetic_energy / (0.3 * total_mass * launch.expansion_speed * launch.expansion_speed);
}

double similarity_energy_ratio(const Cloud& cloud, const Launch& launch) {
  return similarity_energy_ratio(kinetic_energy(cloud), cloud.state().col(MASS).sum(), launch);
}

}  // namespace dlpverify::dlp
