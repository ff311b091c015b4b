// The unit of a problem's time: of its initial time, its end time and every step Δt, as the
// reports write it and the figures label their axes ("Δt [s]"; "Δt" alone when dimensionless).
#pragma once

#include <string>

#include "dlpverify/problem.hpp"

namespace dlpverify {

// The problem's TimeUnit (dlpverify/case_report.hpp), or "s": the cloud, the gas parcels and the
// cooling particles are in SI units, the coupled systems of the staggering study dimensionless.
std::string step_unit(const Problem& problem);

}  // namespace dlpverify
