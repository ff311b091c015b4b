// dlpverify's own N_Vector: SUNDIALS' serial vector layout (one contiguous array of doubles) with
// its arithmetic compiled here, serial or threaded with OpenMP.
//
// Why hand-written: Debian's SUNDIALS 6.4.1 builds its vector kernels without optimisation (-O0,
// every value through the stack; confirmed in the disassembly of N_VLinearSum_Serial), and CVODE
// and ARKODE spend nearly all their time in those loops, not in a cheap right-hand side: the
// same loops compiled here make CVODE 4–5× faster. It is a vector type of its own (its own
// operations table, ID SUNDIALS_NVEC_CUSTOM), not a serial vector with its operations replaced.
//
// Sums (dot product, norms): a vector given its shape (set_shape: members × fields, field-major as
// a population's column-major state) adds one partial per (field, block of 4,096 members) — each
// summed in 16 running partials — in field, then block order, threaded or not, so neither the
// thread count nor a split of the members at block boundaries over processes changes a bit
// (src/mpi/nvector_distributed.hpp adds every rank's partials in that order). A shaped vector
// of at most one block sums in one pass. An unshaped vector sums in chunks of 4,096 entries
// (threaded) or in one pass.
//
// Implemented: creation, clone, destroy, length and array access, every element-wise operation,
// the norms and reductions (and their local forms), linear combination and scale-add-multi.
// Left NULL, so SUNDIALS' generic fallbacks (built from the operations above) apply: the other
// fused and vector-array operations. Left NULL and not used by CVODE or ARKODE without them:
// the constraint operations (N_VConstrMask, N_VMinQuotient: no constraints are set) and the MPI
// buffer operations.
#pragma once

#include <sundials/sundials_nvector.h>

#include <vector>

namespace dlpverify::sun {

// A new vector of `length` entries that owns its data; `threaded` splits long loops over OpenMP.
N_Vector new_compiled_vector(sunindextype length, bool threaded, SUNContext context);
// A vector over `data` (length entries) that neither copies nor frees it.
N_Vector wrap_compiled_vector(double* data, sunindextype length, bool threaded, SUNContext context);
// Whether `v` is one of ours (its operations table is).
bool is_compiled_vector(N_Vector v);

// `v` holds `members` × `fields` entries, field f of member p at f·members + p; its clones too.
// Throws SolverError when the product is not its length.
void set_shape(N_Vector v, sunindextype members, int fields);
struct VectorShape {
  sunindextype members = 0;
  int fields = 0;  // 0: no shape given
};
VectorShape shape_of(N_Vector v);

// The sums of our vectors: x·y, Σ|x|, Σ(x w)², Σ(x w)² over id > 0 (y is w).
enum class VectorSum { dot, l1, weighted_squares, weighted_squares_masked };
// The partial sums of a shaped vector `x` whose total is the sum: with `by_block`, one per
// (field, block of 4,096 members), field by field (index f·blocks + b); without, one over the
// whole vector (none when it is empty). `y` and `id` as the sum needs them, else nullptr.
std::vector<double> partial_sums(VectorSum sum, N_Vector x, N_Vector y, N_Vector id, bool by_block);
// The partials added in their order, as the vector's own sums add them (one partial: itself).
double ordered_total(const std::vector<double>& partials);

}  // namespace dlpverify::sun
