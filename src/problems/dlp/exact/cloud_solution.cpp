#include "problems/dlp/exact/cloud_solution.hpp"

namespace dlpverify::dlp::exact {

Cloud evaluate(ParticleSolution solution, const Physics& physics, const Cloud& initial, double tau) {
  return evaluate(solution, physics, initial.state(), tau);
}

Cloud evaluate(ParticleSolution solution, const Physics& physics, const State& initial, double tau) {
  Cloud result(initial.rows());
#pragma omp parallel for schedule(static)
  for (Eigen::Index p = 0; p < initial.rows(); ++p) {
    ParticleState y;
    for (int f = 0; f < kFields; ++f) y[static_cast<std::size_t>(f)] = initial(p, f);
    result.set_particle(p, solution(physics, y, tau));
  }
  return result;
}

}  // namespace dlpverify::dlp::exact
