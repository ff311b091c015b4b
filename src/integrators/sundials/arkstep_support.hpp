// The pieces of ARKStep that our ARKODE integrators share: the Newton solver of implicit stages,
// its counts, and stepping exactly n fixed steps.
#pragma once

#include <arkode/arkode_arkstep.h>

#include "dlpverify/solver_statistics.hpp"
#include "sundials/sundials_support.hpp"

namespace dlpverify::sun {

// The implicit stages' solver: ARKStep's default Newton iteration, each solving (I − γJ) δ = −G
// with J = ∂f/∂y by matrix-free GMRES (arkstep_support.cpp says why). Attach before the memory's
// first step; the solver returned must outlive the memory.
LinearSolver attach_newton_gmres(void* mem, N_Vector y, SUNContext context, const ErrorLog& log);

// Adds ARKODE's Newton and GMRES counts of `mem` to `s`: nonlinear_iterations,
// nonlinear_convergence_failures, linear_iterations, linear_solver_setups, rhs_evals_jacobian and
// the extra linear_convergence_failures.
void add_newton_statistics(void* mem, SolverStatistics& s);

// Exactly `steps` steps of dt from t0, in place in y: one ARKStepEvolve in ARK_ONE_STEP mode per
// step with the stop time t0 + (n+1)·dt, so step n starts at t0 + n·dt exactly (a single
// ARK_NORMAL call drifts: ARKODE accumulates t += h, and past ~1600 steps takes an extra tiny
// step). The step count is checked against ARKStepGetNumSteps. Throws SolverError.
void step_exactly(void* mem, N_Vector y, double t0, double dt, long steps, const ErrorLog& log);

}  // namespace dlpverify::sun
