// What a study may run on more than one rank (docs/mpi.md). Serially everything runs.
#pragma once

#include <string>

#include "dlpverify/integrator.hpp"
#include "dlpverify/reference.hpp"

namespace dlpverify {

// Under mpirun, refuses (InputError naming the "integrator" or the "reference") an integrator that
// steps the whole population at once (a per-member Runge–Kutta method takes the serial run's bits
// on a rank's share; CVODE and ARKODE take its steps, their sums spanning the ranks), an
// integrator reference that does not step each member alone (the others take norms over the
// whole population inside their steps), and a manufactured reference (its ŷ is built from the
// problem it is given: a rank's share is not the whole).
void check_distributable(IntegratorReach reach, const std::string& integrator, const ReferenceSettings& reference);

}  // namespace dlpverify
