// The `check` verdict: is every measured variable's fitted order within P ± tolerance?
//
// A variable whose every level sits at the round-off floor is exact for the method (the
// similarity and gravity cases under RK2) and passes. A variable with fewer than two levels in
// the asymptotic range has no measured order and fails: nothing was proven.
#pragma once

#include <string>
#include <vector>

#include "harness/study.hpp"

namespace dlpverify {

struct CheckVerdict {
  bool passed = true;
  double expected_order = 0.0;
  double tolerance = 0.0;
  std::vector<std::string> findings;  // one line per variable, saying why it passed or failed
};

CheckVerdict check_orders(const StudyResult& study, double expected_order, double tolerance);

}  // namespace dlpverify
