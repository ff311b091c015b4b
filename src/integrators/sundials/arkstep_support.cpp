#include "integrators/sundials/arkstep_support.hpp"

#include <sunlinsol/sunlinsol_spgmr.h>

#include <cstdio>
#include <string>

#include "dlpverify/errors.hpp"

namespace dlpverify::sun {

// Our population's J is block diagonal, one F×F block per member, but in the column-major layout
// (field f of member p at f·N + p) the blocks interleave: SUNDIALS' dense matrix would hold (NF)²
// entries and its band matrix a bandwidth of (F−1)·N, both factorised at O(N³) cost for what is N
// independent F×F systems. Matrix-free GMRES (SUNLinSol_SPGMR, no preconditioner) needs only
// products J·v, which ARKODE forms by one difference quotient of f each, and only whole-vector
// operations, which our compiled N_Vector provides: memory and work linear in N, and the same
// right-hand side in blocks the explicit path calls. Its iterations grow with the spread of the
// members' stiffness (the counts are reported).
LinearSolver attach_newton_gmres(void* mem, N_Vector y, SUNContext context, const ErrorLog& log) {
  LinearSolver linear(SUNLinSol_SPGMR(y, SUN_PREC_NONE, 0, context));  // 0: SPGMR's default Krylov dimension, 5
  check_created(linear.get(), "SUNLinSol_SPGMR");
  check_flag(ARKStepSetLinearSolver(mem, linear.get(), nullptr), "ARKStepSetLinearSolver", FlagFamily::arkode_linear,
             &log);
  return linear;
}

void add_newton_statistics(void* mem, SolverStatistics& s) {
  long newton = 0, newton_failures = 0, krylov = 0, krylov_failures = 0, setups = 0, quotient_evals = 0;
  ARKStepGetNumNonlinSolvIters(mem, &newton);
  ARKStepGetNumNonlinSolvConvFails(mem, &newton_failures);
  ARKStepGetNumLinIters(mem, &krylov);
  ARKStepGetNumLinConvFails(mem, &krylov_failures);
  ARKStepGetNumLinSolvSetups(mem, &setups);
  ARKStepGetNumLinRhsEvals(mem, &quotient_evals);
  s.nonlinear_iterations = newton;
  s.nonlinear_convergence_failures = newton_failures;
  s.linear_iterations = krylov;
  s.linear_solver_setups = setups;
  s.rhs_evals_jacobian = quotient_evals;
  s.extras["linear_convergence_failures"] = krylov_failures;
}

void step_exactly(void* mem, N_Vector y, double t0, double dt, long steps, const ErrorLog& log) {
  double t_reached = t0;
  for (long n = 0; n < steps; ++n) {
    const double t_next = t0 + static_cast<double>(n + 1) * dt;
    check_flag(ARKStepSetStopTime(mem, t_next), "ARKStepSetStopTime", FlagFamily::arkode, &log);
    const int flag = ARKStepEvolve(mem, t_next, y, &t_reached, ARK_ONE_STEP);
    if (flag < 0) {
      double t_failed = t_reached;
      ARKStepGetCurrentTime(mem, &t_failed);
      check_flag(flag, "ARKStepEvolve", FlagFamily::arkode, &log, t_failed);
    }
    if (t_reached != t_next) {
      char message[160];
      std::snprintf(message, sizeof message, "ARKStepEvolve failed: step %ld ended at t = %.17g s, not at %.17g s",
                    n + 1, t_reached, t_next);
      throw SolverError(message);
    }
  }
  long steps_taken = 0;
  ARKStepGetNumSteps(mem, &steps_taken);
  if (steps_taken != steps)
    throw SolverError("ARKStepEvolve failed: took " + std::to_string(steps_taken) + " steps, not " +
                      std::to_string(steps));
}

}  // namespace dlpverify::sun
