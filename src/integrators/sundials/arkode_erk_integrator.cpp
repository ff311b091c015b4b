#include "integrators/sundials/arkode_erk_integrator.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_erk.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <utility>

#include "integrators/sundials/arkstep_support.hpp"
#include "sundials/population_vector.hpp"
#include "sundials/sundials_support.hpp"
#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"

namespace dlpverify {

namespace {

struct NamedErkTable {
  const char* name;
  ARKODE_ERKTableID id;
};

// Every ERK table of arkode_butcher_erk.h (SUNDIALS 6.4.1). Names are checked here, before
// SUNDIALS sees them: ARKodeButcherTable_LoadERKByName prints "[ARKODE ERROR] … Unknown Butcher
// table" to stderr for an unknown name, bypassing any error handler.
#define DLPVERIFY_ERK_TABLE(id) NamedErkTable{#id, id}
constexpr NamedErkTable kErkTables[] = {
    DLPVERIFY_ERK_TABLE(ARKODE_HEUN_EULER_2_1_2),      DLPVERIFY_ERK_TABLE(ARKODE_BOGACKI_SHAMPINE_4_2_3),
    DLPVERIFY_ERK_TABLE(ARKODE_ARK324L2SA_ERK_4_2_3),  DLPVERIFY_ERK_TABLE(ARKODE_ZONNEVELD_5_3_4),
    DLPVERIFY_ERK_TABLE(ARKODE_ARK436L2SA_ERK_6_3_4),  DLPVERIFY_ERK_TABLE(ARKODE_SAYFY_ABURUB_6_3_4),
    DLPVERIFY_ERK_TABLE(ARKODE_CASH_KARP_6_4_5),       DLPVERIFY_ERK_TABLE(ARKODE_FEHLBERG_6_4_5),
    DLPVERIFY_ERK_TABLE(ARKODE_DORMAND_PRINCE_7_4_5),  DLPVERIFY_ERK_TABLE(ARKODE_ARK548L2SA_ERK_8_4_5),
    DLPVERIFY_ERK_TABLE(ARKODE_VERNER_8_5_6),          DLPVERIFY_ERK_TABLE(ARKODE_FEHLBERG_13_7_8),
    DLPVERIFY_ERK_TABLE(ARKODE_KNOTH_WOLKE_3_3),       DLPVERIFY_ERK_TABLE(ARKODE_ARK437L2SA_ERK_7_3_4),
    DLPVERIFY_ERK_TABLE(ARKODE_ARK548L2SAb_ERK_8_4_5),
};
#undef DLPVERIFY_ERK_TABLE
static_assert(std::size(kErkTables) == ARKODE_MAX_ERK_NUM - ARKODE_MIN_ERK_NUM + 1,
              "this SUNDIALS has ERK tables the list above does not name");

sun::ButcherTable load_table(ARKODE_ERKTableID id) {
  sun::ButcherTable table(ARKodeButcherTable_LoadERK(id));
  sun::check_created(table.get(), "ARKodeButcherTable_LoadERK");
  return table;
}

const NamedErkTable* find_table(const std::string& name) {
  for (const NamedErkTable& table : kErkTables)
    if (name == table.name) return &table;
  return nullptr;
}

}  // namespace

const std::vector<ArkodeTableInfo>& arkode_erk_tables() {
  static const std::vector<ArkodeTableInfo> tables = [] {
    std::vector<ArkodeTableInfo> list;
    for (const NamedErkTable& named : kErkTables) {
      const sun::ButcherTable table = load_table(named.id);
      list.push_back({named.name, table->stages, table->q, table->p});
    }
    return list;
  }();
  return tables;
}

// Declaration order is destruction order reversed: ARKODE's memory goes first, the context last.
struct ArkodeErkIntegrator::Solver {
  sun::Context context;
  sun::ErrorLog log;        // ARKODE's messages, at a stable address (heap)
  sun::ProblemRhsData rhs;  // the user data of problem_rhs, likewise
  sunindextype length = 0;  // F·N of the state this solver was built for
  sun::ArkstepMemory memory;
};

ButcherCoefficients ArkodeErkIntegrator::butcher() const {
  const sun::ButcherTable table = load_table(find_table(table_.name)->id);
  ButcherCoefficients coefficients;
  const int s = table->stages;
  coefficients.a.assign(s, std::vector<double>(s, 0.0));
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) coefficients.a[i][j] = table->A[i][j];
    coefficients.b.push_back(table->b[i]);
    coefficients.c.push_back(table->c[i]);
  }
  return coefficients;
}

ArkodeErkIntegrator::ArkodeErkIntegrator(const std::string& table, bool openmp_vector, bool across_ranks)
    : openmp_vector_(openmp_vector), across_ranks_(across_ranks) {
  for (const ArkodeTableInfo& info : arkode_erk_tables())
    if (info.name == table) table_ = info;
  if (table_.name.empty()) throw InputError("integrator", "arkode-erk:" + table, "unknown ARKODE table");
}

ArkodeErkIntegrator::~ArkodeErkIntegrator() = default;
ArkodeErkIntegrator::ArkodeErkIntegrator(ArkodeErkIntegrator&&) noexcept = default;
ArkodeErkIntegrator& ArkodeErkIntegrator::operator=(ArkodeErkIntegrator&&) noexcept = default;

void ArkodeErkIntegrator::advance(const Problem& problem, State& state, double t0, double dt, long steps) {
  using sun::FlagFamily;
  statistics_ = SolverStatistics{};
  const Eigen::Index particles = state.rows();
  // A rank without members still takes part in every sum of the others (across_ranks).
  if (!sun::advance_has_work(dt, steps, across_ranks_ ? 1 : particles)) return;
  check_shape(problem, state, "state");
  // Across ranks, an agreement before any vector exists (harness/distribution.hpp): a rank that
  // failed before this advance stops every rank here rather than inside a sum of the vector.
  if (across_ranks_) distribution().any(false);

  const auto length = static_cast<sunindextype>(particles) * state.cols();
  std::unique_ptr<Solver> fresh;
  Solver* s = solver_.get();
  if (s == nullptr || s->length != length) {
    fresh = std::make_unique<Solver>();
    s = fresh.get();
  }
  // ARKODE evolves in place in the output vector, which wraps the cloud's buffer.
  sun::Vector y = sun::wrap_population(state, openmp_vector_, s->context, true, across_ranks_);
  s->rhs = {&problem, static_cast<sunindextype>(particles)};
  s->log.clear();

  if (fresh) {
    s->length = length;
    s->memory.reset(ARKStepCreate(sun::problem_rhs, nullptr, t0, y.get(), s->context));
    sun::check_created(s->memory.get(), "ARKStepCreate");
    void* mem = s->memory.get();
    sun::check_flag(ARKStepSetErrHandlerFn(mem, sun::ErrorLog::handler, &s->log), "ARKStepSetErrHandlerFn",
                    FlagFamily::arkode);
    sun::check_flag(ARKStepSetUserData(mem, &s->rhs), "ARKStepSetUserData", FlagFamily::arkode, &s->log);
    // Explicit only: no implicit table. ARKStep keeps its own copy of the table.
    const sun::ButcherTable table = load_table(find_table(table_.name)->id);
    sun::check_flag(ARKStepSetTables(mem, table->q, table->p, nullptr, table.get()), "ARKStepSetTables",
                    FlagFamily::arkode, &s->log);
  } else {
    sun::check_flag(ARKStepReInit(s->memory.get(), sun::problem_rhs, nullptr, t0, y.get()), "ARKStepReInit",
                    FlagFamily::arkode, &s->log);
  }
  void* mem = s->memory.get();
  sun::check_flag(ARKStepSetFixedStep(mem, dt), "ARKStepSetFixedStep", FlagFamily::arkode, &s->log);
  if (fresh) solver_ = std::move(fresh);  // fully set up: keep it for the next advance()

  sun::step_exactly(mem, y.get(), t0, dt, steps, s->log);

  long steps_taken = 0, rhs_evals = 0, implicit_rhs_evals = 0;
  ARKStepGetNumSteps(mem, &steps_taken);
  ARKStepGetNumRhsEvals(mem, &rhs_evals, &implicit_rhs_evals);
  statistics_ = SolverStatistics{};
  statistics_.steps = steps_taken;
  statistics_.rhs_evals = rhs_evals;
  statistics_.extras = {{"table", table_.name},
                        {"order", static_cast<long>(table_.order)},
                        {"stages", static_cast<long>(table_.stages)},
                        {"warnings", s->log.warnings()}};
}

SolverStatistics ArkodeErkIntegrator::statistics() const { return statistics_; }

std::unique_ptr<Integrator> make_sundials_integrator(const std::string& name, const CvodeSettings& settings) {
  if (name == "cvode") return std::make_unique<CvodeIntegrator>(settings);
  const std::string prefix = "arkode-erk:";
  if (name.rfind(prefix, 0) == 0)
    return std::make_unique<ArkodeErkIntegrator>(name.substr(prefix.size()), settings.openmp_vector,
                                                 settings.across_ranks);
  throw InputError("integrator", name, "unknown integrator");
}

}  // namespace dlpverify
