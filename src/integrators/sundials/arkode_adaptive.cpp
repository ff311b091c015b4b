#include "integrators/sundials/arkode_adaptive.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_erk.h>

#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"
#include "integrators/sundials/arkode_dirk_tables.hpp"
#include "integrators/sundials/arkstep_support.hpp"
#include "sundials/population_vector.hpp"
#include "sundials/sundials_support.hpp"

namespace dlpverify {

namespace {

using sun::FlagFamily;

// The table's Butcher coefficients: ARKODE's own, by name (checked before it sees the name).
sun::ButcherTable load_table(const ArkodeAdaptiveTable& table) {
  if (table.implicit) return load_arkode_dirk_table(table.info.name);
  sun::ButcherTable loaded(ARKodeButcherTable_LoadERKByName(table.info.name.c_str()));
  sun::check_created(loaded.get(), "ARKodeButcherTable_LoadERKByName");
  return loaded;
}

// ARKODE's typed counts of the solve, the Newton and GMRES ones for an implicit table.
SolverStatistics read_statistics(void* mem, bool implicit) {
  SolverStatistics s;
  long steps = 0, explicit_evals = 0, implicit_evals = 0, rejected = 0;
  ARKStepGetNumSteps(mem, &steps);
  ARKStepGetNumRhsEvals(mem, &explicit_evals, &implicit_evals);
  ARKStepGetNumErrTestFails(mem, &rejected);
  s.steps = steps;
  s.rhs_evals = explicit_evals + implicit_evals;
  s.error_test_failures = rejected;
  if (implicit) sun::add_newton_statistics(mem, s);
  return s;
}

}  // namespace

const std::vector<ArkodeAdaptiveTable>& arkode_adaptive_tables() {
  static const std::vector<ArkodeAdaptiveTable> tables = [] {
    std::vector<ArkodeAdaptiveTable> list;
    for (const ArkodeTableInfo& info : arkode_erk_tables())
      if (info.embedding_order > 0) list.push_back({info, false});
    for (const ArkodeTableInfo& info : arkode_dirk_tables())
      if (info.embedding_order > 0) list.push_back({info, true});
    return list;
  }();
  return tables;
}

ArkodeAdaptiveTable check_arkode_adaptive_table(const std::string& table) {
  for (const ArkodeAdaptiveTable& known : arkode_adaptive_tables())
    if (known.info.name == table) return known;
  for (const ArkodeTableInfo& info : arkode_erk_tables())
    if (info.name == table)
      throw InputError("integrator", "arkode-adaptive:" + table, "the table has no embedding to adapt its step by");
  throw InputError("integrator", "arkode-adaptive:" + table,
                   "unknown ARKODE table (the ERK and DIRK tables with an embedding: see `dlpverify cases`)");
}

void solve_arkode_adaptive(const Problem& problem, State& state, double t0, double t_final,
                           const ArkodeAdaptiveSettings& settings, SolverStatistics& statistics) {
  const ArkodeAdaptiveTable table = check_arkode_adaptive_table(settings.table);  // before SUNDIALS prints to stderr
  check_shape(problem, state, "state");
  statistics = SolverStatistics{};
  const auto members = static_cast<sunindextype>(state.rows());
  const sunindextype length = members * state.cols();
  // A rank without members still takes part in every sum of the others (across_ranks), after an
  // agreement before any vector exists (harness/distribution.hpp).
  if (length == 0 && !settings.across_ranks) return;
  if (settings.across_ranks) distribution().any(false);
  sun::Context context;
  sun::ErrorLog log;
  sun::ProblemRhsData rhs{&problem, members};
  // The population's vector: shaped (members × fields), so its sums go in the fixed order that
  // makes them the same on any number of ranks (sundials/population_vector.hpp).
  sun::Vector y = sun::wrap_population(state, false, context, true, settings.across_ranks);
  // The absolute tolerance of field f for every member, in the state's column-major layout: a
  // vector of y's kind (spanning the ranks as it does).
  sun::Vector absolute(N_VClone(y.get()));
  sun::check_created(absolute.get(), "N_VClone");
  double* atol_entries = N_VGetArrayPointer(absolute.get());
  for (Eigen::Index f = 0; f < state.cols(); ++f)
    std::fill_n(atol_entries + f * state.rows(), state.rows(), settings.atol.at(static_cast<std::size_t>(f)));
  sun::LinearSolver linear;  // declared before ARKODE's memory, which uses it: freed after it
  sun::ArkstepMemory memory(table.implicit ? ARKStepCreate(nullptr, sun::problem_rhs, t0, y.get(), context)
                                           : ARKStepCreate(sun::problem_rhs, nullptr, t0, y.get(), context));
  sun::check_created(memory.get(), "ARKStepCreate");
  void* mem = memory.get();
  sun::check_flag(ARKStepSetErrHandlerFn(mem, sun::ErrorLog::handler, &log), "ARKStepSetErrHandlerFn", FlagFamily::arkode);
  sun::check_flag(ARKStepSetUserData(mem, &rhs), "ARKStepSetUserData", FlagFamily::arkode, &log);
  const sun::ButcherTable butcher = load_table(table);
  sun::check_flag(ARKStepSetTables(mem, butcher->q, butcher->p, table.implicit ? butcher.get() : nullptr,
                                   table.implicit ? nullptr : butcher.get()),
                  "ARKStepSetTables", FlagFamily::arkode, &log);
  if (table.implicit) linear = sun::attach_newton_gmres(mem, y.get(), context, log);
  sun::check_flag(ARKStepSVtolerances(mem, settings.rtol, absolute.get()), "ARKStepSVtolerances", FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSetMaxNumSteps(mem, settings.max_steps), "ARKStepSetMaxNumSteps", FlagFamily::arkode, &log);
  sun::check_flag(ARKStepSetStopTime(mem, t_final), "ARKStepSetStopTime", FlagFamily::arkode, &log);
  double t_reached = t0;
  const int flag = ARKStepEvolve(mem, t_final, y.get(), &t_reached, ARK_NORMAL);
  if (flag < 0) sun::check_flag(flag, "ARKStepEvolve", FlagFamily::arkode, &log, t_reached);
  statistics = read_statistics(mem, table.implicit);
  statistics.extras.insert({{"table", settings.table}, {"rtol", settings.rtol}, {"warnings", log.warnings()}});
}

}  // namespace dlpverify
