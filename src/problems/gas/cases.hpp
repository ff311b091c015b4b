// The gas-adiabat cases (docs/model.md §7.1): one gas each, the same parcel population and paths.
#pragma once

#include <string>
#include <vector>

#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"
#include "problems/gas/material.hpp"

namespace dlpverify::gas {

struct GasCase {
  std::string name;
  std::string summary;
  std::string gas;   // what gas the defaults describe
  MolarSpec spec;    // its reference state and constants
  StudyDefaults defaults;
};

// adiabat-ideal (air), adiabat-vdw (carbon dioxide at 20 bar).
const std::vector<GasCase>& all_gas_cases();
// The gas case of that name, or nullptr.
const GasCase* find_gas_case(const std::string& name);

}  // namespace dlpverify::gas
