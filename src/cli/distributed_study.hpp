// A convergence study or a work-precision sweep under mpirun (docs/mpi.md): what it may be asked
// to run.
#pragma once

#include <string>

#include "dlpverify/reference.hpp"
#include "harness/distribution.hpp"

namespace dlpverify::cli {

// Refuses (InputError naming the option) what does not yet run on more than one rank: an
// integrator that is neither a per-member Runge–Kutta method nor CVODE or ARKODE ERK (whose sums
// span the ranks), an integrator reference that is not a per-member method (the others take norms
// over the whole population inside their steps), and a manufactured reference.
void check_distributable(const std::string& integrator, const ReferenceSettings& reference);

}  // namespace dlpverify::cli
