// The N_Vector over a whole population's state (N members × F fields, column-major: field f of
// member p at f·N + p) that CVODE and ARKODE step: our compiled vector, told its shape so that its
// sums go by (field, block of members) (nvector_compiled.hpp). Under mpirun, when the state is
// this rank's share of a population spread over the ranks (docs/mpi.md), that vector is wrapped
// so that its sums span every rank: src/mpi/nvector_distributed.hpp, installed by the command,
// since this library does not link MPI.
#pragma once

#include "dlpverify/problem.hpp"
#include "sundials/sundials_support.hpp"

namespace dlpverify::sun {

// From this rank's shaped compiled vector (which it takes over, destroyed with the result), a
// vector whose reductions span every rank; nullptr when it cannot be made.
using RankSpanningVector = N_Vector (*)(N_Vector local, SUNContext context);
// Installs `make` (nullptr: none, as serially).
void install_rank_spanning_vector(RankSpanningVector make);

// A vector over `state` that neither copies nor owns it: our compiled vector (threaded with
// `openmp`) shaped as the state, or with `compiled` false SUNDIALS' own serial or OpenMP vector;
// with `across_ranks`, the rank-spanning vector over it. Throws SolverError when that is asked
// and none is installed or it cannot be made, or of SUNDIALS' own vectors.
Vector wrap_population(State& state, bool openmp, SUNContext context, bool compiled, bool across_ranks);

}  // namespace dlpverify::sun
