// CVODE's and ARKODE's state vector when a population is spread over the MPI ranks (docs/mpi.md):
// SUNDIALS' MPIPlusX vector over this rank's slab — our compiled vector, shaped as the slab's
// members × fields (src/sundials/nvector_compiled.hpp) — whose element-wise operations are the
// slab's own and whose sums span every rank in the serial run's order:
//
//   x·y, Σ|x|, Σ(x w)² (wrms, masked wrms, wl2): each rank's (field, block of 4,096 members)
//     partials, gathered (MPI_Allgatherv; ranks hold contiguous runs of whole blocks in rank
//     order, harness/distribution.hpp) and added field by field, then block by block: the serial
//     vector's partials, added in its order, so the same bits on any number of ranks. A population
//     of one block is one partial, the rank's that holds it. wrms divides by the global length.
//   max norm, min: MPI_Allreduce (exact in any order); the inverse test, the constraint mask and
//     the minimum quotient: SUNDIALS' own (a local test or minimum, then MPI_Allreduce).
//   Fused reductions over several vectors (dot products of many, wrms of arrays): NULL, so
//     SUNDIALS falls back to the single-vector sums above. The other fused operations are on and
//     go to the slab's own, as serially.
//
// Every rank takes the same decisions, so a solver failure is every rank's: CVODE's tests see
// only these global sums, and the right-hand side reports no failure (an exception escaping it
// would end the process, serially too). So the sums need not open with the session's agreement;
// an MPI error inside one makes it NaN, which fails the step on every rank.
#pragma once

#include <sundials/sundials_nvector.h>

namespace dlpverify::mpi {

// The vector over this rank's shaped compiled vector `local` (taken over: destroyed with the
// result, or at once when nullptr is returned) on MPI_COMM_WORLD. Collective. nullptr when
// `local` has no shape or its members are not this rank's share of the population
// (own_members); matches sun::RankSpanningVector (src/sundials/population_vector.hpp).
N_Vector distributed_vector(N_Vector local, SUNContext context);

}  // namespace dlpverify::mpi
