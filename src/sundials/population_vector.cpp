#include "sundials/population_vector.hpp"

#include "dlpverify/errors.hpp"
#include "sundials/nvector_compiled.hpp"

namespace dlpverify::sun {

namespace {
RankSpanningVector installed = nullptr;
}  // namespace

void install_rank_spanning_vector(RankSpanningVector make) { installed = make; }

Vector wrap_population(State& state, bool openmp, SUNContext context, bool compiled, bool across_ranks) {
  const auto members = static_cast<sunindextype>(state.rows());
  const auto fields = static_cast<int>(state.cols());
  Vector local = wrap_vector(state.data(), members * fields, openmp, context, compiled);
  if (compiled) set_shape(local.get(), members, fields);
  if (!across_ranks) return local;
  if (installed == nullptr || !compiled)
    throw SolverError("the population's vector cannot span the ranks: " +
                      std::string(installed == nullptr ? "no MPI vector in this build" : "SUNDIALS' own vectors do not"));
  Vector spanning(installed(local.release(), context));
  check_created(spanning.get(), "the rank-spanning vector");
  return spanning;
}

}  // namespace dlpverify::sun
