#include "study/distributable.hpp"

#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"

namespace dlpverify {

void check_distributable(IntegratorReach reach, const std::string& integrator, const ReferenceSettings& reference) {
  if (distribution().ranks() == 1) return;
  if (reach == IntegratorReach::whole_population)
    throw InputError("integrator", integrator,
                     "steps the whole population at once; under mpirun an integrator steps each member alone (a "
                     "Runge–Kutta method) or spans the ranks (CVODE, ARKODE) (docs/mpi.md)");
  if (reference.kind == ReferenceKind::manufactured)
    throw InputError("reference", "manufactured",
                     "its manufactured solution is built from the whole population; under mpirun use the closed form, "
                     "CVODE or an integrator reference (docs/mpi.md)");
  if (reference.kind == ReferenceKind::integrator && reference.integrator &&
      reference.integrator_reach != IntegratorReach::each_member)
    throw InputError("reference", "integrator:" + reference.integrator->name(),
                     "steps the whole population at once; under mpirun an integrator reference steps each member "
                     "alone, a Runge–Kutta method (docs/mpi.md)");
}

}  // namespace dlpverify
