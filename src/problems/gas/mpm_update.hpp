// NairnMPM's adiabatic temperature update, and its second-order correction, as integrators of the
// gas cases (docs/model.md §7.1). A production code does not integrate dT/dt: each step it moves
// the parcel from J_n to J_{n+1} along the prescribed path and updates T from the work of the step.
// These integrators do the same over every parcel, so the harness measures that update's order.
// They know the gas problem (its material and paths) and refuse any other problem.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dlpverify/integrator.hpp"

namespace dlpverify::gas {

struct UpdateInfo {
  std::string name;
  int order;
  std::string summary;
};

// mpm-trapezoid (as published) and mpm-trapezoid-corrected.
std::vector<UpdateInfo> temperature_updates();
// The update of that name, or nullptr when the name is not one of them.
std::unique_ptr<Integrator> make_temperature_update(const std::string& name);

}  // namespace dlpverify::gas
