// ARKODE's explicit Runge–Kutta tables with an embedding, adaptive (`arkode-adaptive:TABLE`, for
// a study by tolerance): ARKStep, fe = f, fi = NULL, the table's embedded error estimate held to
// rtol and a per-field absolute tolerance, from t0 to t_final in one ARK_NORMAL call.
#pragma once

#include <string>
#include <vector>

#include "dlpverify/problem.hpp"
#include "dlpverify/solver_statistics.hpp"

namespace dlpverify {

struct ArkodeAdaptiveSettings {
  std::string table;         // an ERK table of arkode_erk_tables() with an embedding
  double rtol = 1e-6;
  std::vector<double> atol;  // per field (absolute_tolerances)
  long max_steps = 100000;
};

// Throws InputError naming --integrator for a table that is unknown or has no embedding.
void check_arkode_adaptive_table(const std::string& table);

// `state` from t0 to t_final; fills steps, rhs_evals and error_test_failures (rejected steps).
// Throws SolverError when ARKODE fails.
void solve_arkode_adaptive(const Problem& problem, State& state, double t0, double t_final,
                           const ArkodeAdaptiveSettings& settings, SolverStatistics& statistics);

}  // namespace dlpverify
