#include "integrators/sundials/arkode_adaptive.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_erk.h>

#include "dlpverify/errors.hpp"
#include "integrators/sundials/arkode_erk_integrator.hpp"
#include "sundials/sundials_support.hpp"

namespace dlpverify {

void check_arkode_adaptive_table(const std::string& table) {
  for (const ArkodeTableInfo& info : arkode_erk_tables()) {
    if (info.name != table) continue;
    if (info.embedding_order <= 0)
      throw InputError("--integrator", "arkode-adaptive:" + table, "the table has no embedding to adapt its step by");
    return;
  }
  throw InputError("--integrator", "arkode-adaptive:" + table, "unknown ARKODE table");
}

void solve_arkode_adaptive(const Problem& problem, State& state, double t0, double t_final,
                           const ArkodeAdaptiveSettings& settings, SolverStatistics& statistics) {
  using sun::FlagFamily;
  check_arkode_adaptive_table(settings.table);  // before SUNDIALS prints to stderr for an unknown name
  check_shape(problem, state, "state");
  statistics = SolverStatistics{};
  const auto members = static_cast<sunindextype>(state.rows());
  const sunindextype length = members * state.cols();
  if (length == 0) return;
  sun::Context context;
  sun::ErrorLog log;
  sun::ProblemRhsData rhs{&problem, members};
  // The absolute tolerance of field f for every member, in the state's column-major layout.
  State atol(state.rows(), state.cols());
  for (Eigen::Index f = 0; f < state.cols(); ++f) atol.col(f).setConstant(settings.atol.at(static_cast<std::size_t>(f)));
  sun::Vector y = sun::wrap_vector(state.data(), length, false, context);
  sun::Vector absolute = sun::wrap_vector(atol.data(), length, false, context);
  sun::ArkstepMemory memory(ARKStepCreate(sun::problem_rhs, nullptr, t0, y.get(), context));
  sun::check_created(memory.get(), "ARKStepCreate");
  void* mem = memory.get();
  sun::check_flag(ARKStepSetErrHandlerFn(mem, sun::ErrorLog::handler, &log), "ARKStepSetErrHandlerFn", FlagFamily::arkode);
  sun::check_flag(ARKStepSetUserData(mem, &rhs), "ARKStepSetUserData", FlagFamily::arkode, &log);
  const sun::ButcherTable table(ARKodeButcherTable_LoadERKByName(settings.table.c_str()));
  sun::check_created(table.get(), "ARKodeButcherTable_LoadERKByName");
  sun::check_flag(ARKStepSetTables(mem, table->q, table->p, nullptr, table.get()), "ARKStepSetTables",
                  FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSVtolerances(mem, settings.rtol, absolute.get()), "ARKStepSVtolerances", FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSetMaxNumSteps(mem, settings.max_steps), "ARKStepSetMaxNumSteps", FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSetStopTime(mem, t_final), "ARKStepSetStopTime", FlagFamily::arkode, &log);
  double t_reached = t0;
  const int flag = ARKStepEvolve(mem, t_final, y.get(), &t_reached, ARK_NORMAL);
  if (flag < 0) sun::check_flag(flag, "ARKStepEvolve", FlagFamily::arkode, &log, t_reached);

  long steps = 0, rhs_evals = 0, implicit_rhs_evals = 0, error_test_failures = 0;
  ARKStepGetNumSteps(mem, &steps);
  ARKStepGetNumRhsEvals(mem, &rhs_evals, &implicit_rhs_evals);
  ARKStepGetNumErrTestFails(mem, &error_test_failures);
  statistics.steps = steps;
  statistics.rhs_evals = rhs_evals;
  statistics.error_test_failures = error_test_failures;
  statistics.extras = {{"table", settings.table}, {"rtol", settings.rtol}, {"warnings", log.warnings()}};
}

}  // namespace dlpverify
