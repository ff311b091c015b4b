#include "integrators/sundials/arkode_dirk_integrator.hpp"

#include <arkode/arkode_arkstep.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "integrators/sundials/arkstep_support.hpp"
#include "sundials/population_vector.hpp"
#include "sundials/sundials_support.hpp"

namespace dlpverify {

namespace {

// ARKODE's copy of the table: s stages, no embedding (p = 0), A row-major, and the order ARKODE is
// told, q = max(order, 2): told 1, ARKStep 6.4.1 hands back the mean of each step's two ends
// (backward Euler on y' = −3y, Δt = 0.1: 0.8846 = (1 + 1/1.3)/2 for 1/1.3, measured). The order
// steers only ARKODE's step adaptivity and interpolant, never the fixed step's coefficients.
sun::ButcherTable butcher_table(const DirkTable& table, int order) {
  const int s = static_cast<int>(table.b.size());
  std::vector<double> c = table.c, b = table.b, a;
  for (const std::vector<double>& row : table.a) a.insert(a.end(), row.begin(), row.end());
  sun::ButcherTable butcher(ARKodeButcherTable_Create(s, std::max(order, 2), 0, c.data(), a.data(), b.data(), nullptr));
  sun::check_created(butcher.get(), "ARKodeButcherTable_Create");
  return butcher;
}

}  // namespace

ArkodeDirkIntegrator::ArkodeDirkIntegrator(std::string name, int order, DirkTable table)
    : name_(std::move(name)), order_(order), table_(std::move(table)) {}

void ArkodeDirkIntegrator::advance(const Problem& problem, State& state, double t0, double dt, long steps) {
  using sun::FlagFamily;
  check_step(dt, steps);
  statistics_ = SolverStatistics{};
  if (steps == 0 || state.size() == 0) return;
  check_shape(problem, state, "state");
  const double size = state.cwiseAbs().maxCoeff();
  sun::Context context;
  sun::ErrorLog log;
  sun::ProblemRhsData rhs{&problem, static_cast<sunindextype>(state.rows())};
  sun::Vector y = sun::wrap_population(state, false, context, true, false);
  sun::LinearSolver linear;  // declared before ARKODE's memory, which uses it: freed after it
  sun::ArkstepMemory memory(ARKStepCreate(nullptr, sun::problem_rhs, t0, y.get(), context));
  sun::check_created(memory.get(), "ARKStepCreate");
  void* mem = memory.get();
  sun::check_flag(ARKStepSetErrHandlerFn(mem, sun::ErrorLog::handler, &log), "ARKStepSetErrHandlerFn", FlagFamily::arkode);
  sun::check_flag(ARKStepSetUserData(mem, &rhs), "ARKStepSetUserData", FlagFamily::arkode, &log);
  const sun::ButcherTable butcher = butcher_table(table_, order_);
  sun::check_flag(ARKStepSetTables(mem, butcher->q, 0, butcher.get(), nullptr), "ARKStepSetTables", FlagFamily::arkode, &log);
  linear = sun::attach_newton_gmres(mem, y.get(), context, log);
  // The Newton test's weights: relative and absolute alike, the latter on the state's largest entry.
  const double absolute = size > 0.0 ? kNewtonRelative * size : kNewtonRelative;
  sun::check_flag(ARKStepSStolerances(mem, kNewtonRelative, absolute), "ARKStepSStolerances", FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSetNonlinConvCoef(mem, kNewtonTolerance), "ARKStepSetNonlinConvCoef", FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSetMaxNonlinIters(mem, kNewtonIterations), "ARKStepSetMaxNonlinIters", FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSetFixedStep(mem, dt), "ARKStepSetFixedStep", FlagFamily::arkode, &log);
  sun::step_exactly(mem, y.get(), t0, dt, steps, log);

  long steps_taken = 0, explicit_evals = 0, implicit_evals = 0;
  ARKStepGetNumSteps(mem, &steps_taken);
  ARKStepGetNumRhsEvals(mem, &explicit_evals, &implicit_evals);
  statistics_.steps = steps_taken;
  statistics_.rhs_evals = explicit_evals + implicit_evals;
  sun::add_newton_statistics(mem, statistics_);
  statistics_.extras["newton_tolerance"] = kNewtonTolerance;
  statistics_.extras["newton_relative_weight"] = kNewtonRelative;
  statistics_.extras["warnings"] = log.warnings();
  if (const long failures = statistics_.nonlinear_convergence_failures.value_or(0); failures > 0)
    throw SolverError(name_ + ": Newton's iteration did not converge to a correction of " +
                      std::to_string(kNewtonTolerance) + " (weighted RMS) within " + std::to_string(kNewtonIterations) +
                      " iterations in " + std::to_string(failures) + " stage solve(s)");
}

}  // namespace dlpverify
