#include "integrators/implicit/integrators.hpp"

#include "integrators/implicit/fixed_point.hpp"
#include "integrators/implicit/staggered_euler.hpp"

namespace dlpverify::implicit {

std::vector<IntegratorInfo> implicit_integrators() {
  const IntegratorTraits whole;  // iterates on the whole population, by the problem's right-hand side
  return {{"implicit-fp", 1, "backward Euler by fixed-point iteration, linear decay exact (Zohdi's cooling update)", whole},
          {"stagger-jacobi", 1, "backward Euler by staggering: each field block solved with the others frozen, Jacobi", whole},
          {"stagger-gauss-seidel", 1, "backward Euler by staggering, Gauss-Seidel (newest values of earlier blocks)", whole}};
}

std::unique_ptr<Integrator> make_implicit_integrator(const std::string& name) {
  if (name == "implicit-fp") return std::make_unique<FixedPointEuler>();
  if (name == "stagger-jacobi") return std::make_unique<StaggeredEuler>(Sweep::jacobi);
  if (name == "stagger-gauss-seidel") return std::make_unique<StaggeredEuler>(Sweep::gauss_seidel);
  return nullptr;
}

}  // namespace dlpverify::implicit
