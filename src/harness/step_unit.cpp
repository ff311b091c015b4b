#include "harness/step_unit.hpp"

#include "dlpverify/case_report.hpp"

namespace dlpverify {

std::string step_unit(const Problem& problem) {
  const TimeUnit* unit = problem.capability<TimeUnit>();
  return unit ? unit->time_unit() : "s";
}

}  // namespace dlpverify
