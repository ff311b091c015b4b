#include "problems/dlp/kinetic_energy.hpp"

namespace dlpverify::dlp {

double kinetic_energy(const Cloud& cloud) {
  const auto& s = cloud.state();
  const auto speed_squared = s.col(VX).square() + s.col(VY).square() + s.col(VZ).square();
  return 0.5 * (s.col(MASS) * speed_squared).sum();
}

double similarity_energy_ratio(const Cloud& cloud, const Launch& launch) {
  const double total_mass = cloud.state().col(MASS).sum();
  return kinetic_energy(cloud) / (0.3 * total_mass * launch.expansion_speed * launch.expansion_speed);
}

}  // namespace dlpverify::dlp
