// ARKODE's Runge–Kutta tables with an embedding, adaptive (`arkode-adaptive:TABLE`, for a study
// by tolerance): ARKStep with the table's embedded error estimate held to rtol and a per-field
// absolute tolerance, from t0 to t_final in one ARK_NORMAL call. An explicit (ERK) table steps
// fe = f, fi = NULL; an implicit (DIRK) table fe = NULL, fi = f, its stages solved by Newton's
// method with matrix-free GMRES (arkstep_support.cpp says why).
#pragma once

#include <string>
#include <vector>

#include "dlpverify/problem.hpp"
#include "dlpverify/solver_statistics.hpp"
#include "integrators/sundials/arkode_erk_integrator.hpp"  // ArkodeTableInfo

namespace dlpverify {

// A table arkode-adaptive can step with: explicit or implicit, and its orders.
struct ArkodeAdaptiveTable {
  ArkodeTableInfo info;
  bool implicit = false;  // a DIRK table of arkode_butcher_dirk.h, else an ERK table
};

// Every ERK and DIRK table of this SUNDIALS that has an embedding, explicit ones first.
const std::vector<ArkodeAdaptiveTable>& arkode_adaptive_tables();

struct ArkodeAdaptiveSettings {
  std::string table;         // a name of arkode_adaptive_tables()
  double rtol = 1e-6;
  std::vector<double> atol;  // per field (absolute_tolerances)
  long max_steps = 100000;
  bool across_ranks = false;  // under mpirun: the state is this rank's members, the sums span every rank
                              // (as CvodeSettings::across_ranks)
};

// The table of that name. Throws InputError naming --integrator for a table that is unknown or
// has no embedding.
ArkodeAdaptiveTable check_arkode_adaptive_table(const std::string& table);

// `state` from t0 to t_final; fills steps, rhs_evals (fe + fi) and error_test_failures (rejected
// steps), and for an implicit table the Newton and GMRES counts (nonlinear_iterations,
// nonlinear_convergence_failures, linear_iterations, linear_solver_setups, rhs_evals_jacobian =
// the difference quotients' evaluations, and the extra linear_convergence_failures).
// Throws SolverError when ARKODE fails.
void solve_arkode_adaptive(const Problem& problem, State& state, double t0, double t_final,
                           const ArkodeAdaptiveSettings& settings, SolverStatistics& statistics);

}  // namespace dlpverify
