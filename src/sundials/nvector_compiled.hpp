// dlpverify's own N_Vector: SUNDIALS' serial vector layout (one contiguous array of doubles) with
// its arithmetic compiled here, serial or threaded with OpenMP.
//
// Why hand-written: Debian's SUNDIALS 6.4.1 builds its vector kernels without optimisation (-O0,
// every value through the stack; confirmed in the disassembly of N_VLinearSum_Serial), and CVODE
// and ARKODE spend nearly all their time in those loops, not in a cheap right-hand side: the
// same loops compiled here make CVODE 4–5× faster. It is a vector type of its own (its own
// operations table, ID SUNDIALS_NVEC_CUSTOM), not a serial vector with its operations replaced.
//
// Implemented: creation, clone, destroy, length and array access, every element-wise operation,
// the norms and reductions (and their local forms), linear combination and scale-add-multi.
// Left NULL, so SUNDIALS' generic fallbacks (built from the operations above) apply: the other
// fused and vector-array operations. Left NULL and not used by CVODE or ARKODE without them:
// the constraint operations (N_VConstrMask, N_VMinQuotient: no constraints are set) and the MPI
// buffer operations.
#pragma once

#include <sundials/sundials_nvector.h>

namespace dlpverify::sun {

// A new vector of `length` entries that owns its data; `threaded` splits long loops over OpenMP.
N_Vector new_compiled_vector(sunindextype length, bool threaded, SUNContext context);
// A vector over `data` (length entries) that neither copies nor frees it.
N_Vector wrap_compiled_vector(double* data, sunindextype length, bool threaded, SUNContext context);
// Whether `v` is one of ours (its operations table is).
bool is_compiled_vector(N_Vector v);

}  // namespace dlpverify::sun
