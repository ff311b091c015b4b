// The implicit integrators a study can name (docs/model.md §7.3): backward Euler by fixed-point
// iteration and by staggering, for any problem.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dlpverify/integrator.hpp"
#include "integrators/registry.hpp"  // IntegratorInfo

namespace dlpverify::implicit {

// implicit-fp, stagger-jacobi, stagger-gauss-seidel.
std::vector<IntegratorInfo> implicit_integrators();
// The implicit integrator of that name, or nullptr when the name is not one of them.
std::unique_ptr<Integrator> make_implicit_integrator(const std::string& name);

}  // namespace dlpverify::implicit
