#include "problems/dlp/exact/cloud_solution.hpp"

namespace dlpverify::exact {

Cloud evaluate(ParticleSolution solution, const Physics& physics, const Cloud& initial, double tau) {
  Cloud result(initial.size());
#pragma omp parallel for schedule(static)
  for (Eigen::Index p = 0; p < initial.size(); ++p) result.set_particle(p, solution(physics, initial.particle(p), tau));
  return result;
}

}  // namespace dlpverify::exact
