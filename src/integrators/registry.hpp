// The integrators a study can name, and how to make one.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/integrator.hpp"

namespace dlpverify {

struct IntegratorInfo {
  std::string name;
  int order;
  std::string summary;
};

const std::vector<IntegratorInfo>& fixed_step_integrators();

// Makes a fixed-step integrator by name; throws InputError naming --integrator for an unknown one.
std::unique_ptr<Integrator> make_fixed_step_integrator(const std::string& name);

}  // namespace dlpverify
