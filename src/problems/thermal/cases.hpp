// The thermal cases (docs/model.md §7.3): particle cooling, with the physics that gives each of
// its closed forms, and the seed's two coupled systems for staggering.
#pragma once

#include <string>
#include <vector>

#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"
#include "problems/thermal/cooling.hpp"

namespace dlpverify::thermal {

struct ThermalCase {
  std::string name;
  std::string summary;
  std::string terms;   // what the case switches on
  int equations = 0;   // 0: cooling; 2 or 3: the coupled system
  CoolingPhysics physics;  // cooling cases
  StudyDefaults defaults;
};

// cooling, cooling-radiation, cooling-radiation-vacuum, cooling-bernoulli, stagger-2x2, stagger-3x3.
const std::vector<ThermalCase>& all_thermal_cases();
// The thermal case of that name, or nullptr.
const ThermalCase* find_thermal_case(const std::string& name);

}  // namespace dlpverify::thermal
