// Every field of a problem in a group: its measured variables made of fields first, then each
// field that no variable covers as a group of its own. ODE residuals and tolerance scales work
// group by group.
#pragma once

#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

std::vector<Variable> field_groups(const Problem& problem);

}  // namespace dlpverify
