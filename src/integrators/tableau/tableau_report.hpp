// The verdict on a Butcher tableau against its order conditions (order_conditions.hpp) and its
// report: a condition the claimed order relies on and misses fails the tableau; one above the
// claimed order is only "not met" (docs/verification.md, "Your own tableau").
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "integrators/tableau/tableau_file.hpp"

namespace dlpverify {

struct TableauVerdict {
  bool passed = false;    // every condition of the claimed orders is met, to round-off
  std::string table;      // every condition with its verdict, the orders met, the outcome
  nlohmann::json report;  // the JSON result, less the provenance
};

TableauVerdict judge_tableau(const RuntimeTableau& tableau);

}  // namespace dlpverify
