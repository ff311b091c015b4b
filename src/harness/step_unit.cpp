#include "harness/step_unit.hpp"

namespace dlpverify {

std::string step_unit(const Problem&) { return "s"; }

}  // namespace dlpverify
