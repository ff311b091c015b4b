// The unit of a problem's time: of its initial time, its end time and every step Δt, as the
// reports write it and the figures label their axes ("Δt [s]"; "Δt" alone when dimensionless).
#pragma once

#include <string>

#include "dlpverify/problem.hpp"

namespace dlpverify {

// "s" for every problem dlpverify runs (the cloud, the gas parcels, the cooling particles are in
// SI units); "1" for a dimensionless one. The problem is to declare its own unit of time: this
// function is where the reports ask for it.
std::string step_unit(const Problem& problem);

}  // namespace dlpverify
