#include "mpi/nvector_distributed.hpp"

#include <mpi.h>
#include <nvector/nvector_mpiplusx.h>

#include <cmath>
#include <limits>
#include <vector>

#include "harness/compensated_sum.hpp"
#include "harness/distribution.hpp"
#include "sundials/nvector_compiled.hpp"

namespace dlpverify::mpi {

namespace {

using sun::VectorSum;

MPI_Comm communicator(N_Vector v) { return static_cast<N_VectorContent_MPIPlusX>(v->content)->comm; }
N_Vector slab(N_Vector v) { return v != nullptr ? N_VGetLocalVector_MPIPlusX(v) : nullptr; }
constexpr double kFailed = std::numeric_limits<double>::quiet_NaN();

// How many partials each rank sends: fields × its blocks, or one from the rank that holds a
// population of a single block.
struct Layout {
  int fields = 0;
  bool by_block = false;
  std::vector<int> counts, offsets;
  int total = 0;
};

Layout layout(N_Vector x, int ranks) {
  Layout l;
  l.fields = sun::shape_of(slab(x)).fields;
  const sunindextype members = N_VGetLength(x) / l.fields;  // the whole population's
  l.by_block = members > kSumBlock;
  for (int r = 0; r < ranks; ++r) {
    const Eigen::Index held = own_members(members, r, ranks).count;
    const int blocks = static_cast<int>((held + kSumBlock - 1) / kSumBlock);
    l.counts.push_back(l.by_block ? blocks * l.fields : (held > 0 ? 1 : 0));
    l.offsets.push_back(l.total);
    l.total += l.counts.back();
  }
  return l;
}

// Σ over the population: every rank's partials, added in the serial vector's order (field, then
// global block: rank by rank, each rank's blocks in order).
double population_sum(VectorSum sum, N_Vector x, N_Vector y, N_Vector id) {
  const MPI_Comm comm = communicator(x);
  int ranks = 1;
  if (MPI_Comm_size(comm, &ranks) != MPI_SUCCESS) return kFailed;
  const Layout l = layout(x, ranks);
  const std::vector<double> own = sun::partial_sums(sum, slab(x), slab(y), slab(id), l.by_block);
  std::vector<double> all(static_cast<std::size_t>(l.total));
  if (MPI_Allgatherv(own.data(), static_cast<int>(own.size()), MPI_DOUBLE, all.data(), l.counts.data(),
                     l.offsets.data(), MPI_DOUBLE, comm) != MPI_SUCCESS)
    return kFailed;
  if (!l.by_block) return sun::ordered_total(all);
  std::vector<double> ordered;
  ordered.reserve(all.size());
  for (int f = 0; f < l.fields; ++f)
    for (int r = 0; r < ranks; ++r) {
      const int blocks = l.counts[static_cast<std::size_t>(r)] / l.fields;
      const double* held = all.data() + l.offsets[static_cast<std::size_t>(r)] + f * blocks;
      ordered.insert(ordered.end(), held, held + blocks);
    }
  return sun::ordered_total(ordered);
}

double reduced(double local, MPI_Op op, N_Vector x) {
  double global = local;
  if (MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, op, communicator(x)) != MPI_SUCCESS) return kFailed;
  return global;
}

double dot_product(N_Vector x, N_Vector y) { return population_sum(VectorSum::dot, x, y, nullptr); }
double l1_norm(N_Vector x) { return population_sum(VectorSum::l1, x, nullptr, nullptr); }
double wl2_norm(N_Vector x, N_Vector w) { return std::sqrt(population_sum(VectorSum::weighted_squares, x, w, nullptr)); }
double wrms_norm(N_Vector x, N_Vector w) {
  return std::sqrt(population_sum(VectorSum::weighted_squares, x, w, nullptr) / static_cast<double>(N_VGetLength(x)));
}
double wrms_norm_masked(N_Vector x, N_Vector w, N_Vector id) {
  return std::sqrt(population_sum(VectorSum::weighted_squares_masked, x, w, id) / static_cast<double>(N_VGetLength(x)));
}
double max_norm(N_Vector x) { return reduced(N_VMaxNorm(slab(x)), MPI_MAX, x); }
double minimum(N_Vector x) { return reduced(N_VMin(slab(x)), MPI_MIN, x); }

// The fused operations on: MPIPlusX then hands linear combinations and scale-add-multi to the
// slab's own (as the serial vector does them) and the vector-array ones to the slab, where
// SUNDIALS' generic forms run as serially. Then our sums, and no fused sum of SUNDIALS' order.
void install(N_Vector v) {
  N_VEnableFusedOps_MPIPlusX(v, SUNTRUE);
  N_Vector_Ops ops = v->ops;
  ops->nvdotprod = dot_product;
  ops->nvl1norm = l1_norm;
  ops->nvwl2norm = wl2_norm;
  ops->nvwrmsnorm = wrms_norm;
  ops->nvwrmsnormmask = wrms_norm_masked;
  ops->nvmaxnorm = max_norm;
  ops->nvmin = minimum;
  ops->nvdotprodmulti = nullptr;
  ops->nvdotprodmultilocal = nullptr;
  ops->nvdotprodmultiallreduce = nullptr;
  ops->nvwrmsnormvectorarray = nullptr;
  ops->nvwrmsnormmaskvectorarray = nullptr;
}

}  // namespace

N_Vector distributed_vector(N_Vector local, SUNContext context) {
  const sun::VectorShape shape = sun::shape_of(local);
  N_Vector v = shape.fields > 0 ? N_VMake_MPIPlusX(MPI_COMM_WORLD, local, context) : nullptr;
  if (v == nullptr) {
    N_VDestroy(local);
    return nullptr;
  }
  static_cast<N_VectorContent_MPIPlusX>(v->content)->own_data = SUNTRUE;  // destroys `local` with it
  const Eigen::Index members = N_VGetLength(v) / shape.fields;
  if (own_members(members).count != shape.members) {
    N_VDestroy(v);
    return nullptr;
  }
  install(v);  // clones copy the table
  return v;
}

}  // namespace dlpverify::mpi
