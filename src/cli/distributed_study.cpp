#include "cli/distributed_study.hpp"

#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"

namespace dlpverify::cli {

namespace {

bool reaches_each_member(const std::string& integrator) {
  const std::optional<IntegratorTraits> traits = find_integrator_traits(integrator);
  return traits && traits->reach == IntegratorTraits::Reach::each_member;
}

}  // namespace

void check_distributable(const std::string& integrator, const ReferenceSettings& reference) {
  if (distribution().ranks() == 1) return;
  // A Runge–Kutta method steps each member on its own, so a rank's members take the serial run's
  // bits; CVODE and ARKODE step the rank's share in vectors whose sums span every rank
  // (CvodeSettings::across_ranks, src/mpi/nvector_distributed.hpp): the serial run's steps.
  if (integrator_traits(integrator).reach == IntegratorTraits::Reach::whole_population)
    throw InputError("integrator", integrator,
                     "steps the whole population at once; under mpirun use euler, heun, rk2, rk4, tableau:FILE, cvode, "
                     "arkode-erk:TABLE or, with --tolerances, arkode-adaptive:TABLE (docs/mpi.md)");
  // ManufacturedProblem builds ŷ from the problem it is given: a slab's ŷ is not the whole's.
  if (reference.kind == ReferenceKind::manufactured)
    throw InputError("reference", "manufactured",
                     "its manufactured solution is built from the whole population; under mpirun use the closed form, "
                     "cvode or integrator:SPEC@DT (docs/mpi.md)");
  if (reference.kind == ReferenceKind::integrator && reference.integrator &&
      !reaches_each_member(reference.integrator->name()))
    throw InputError("reference", "integrator:" + reference.integrator->name(),
                     "steps the whole population at once; under mpirun an integrator reference is euler, heun, rk2, "
                     "rk4 or tableau:FILE (docs/mpi.md)");
}

}  // namespace dlpverify::cli
