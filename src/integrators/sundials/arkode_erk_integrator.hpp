// ARKODE's explicit Runge–Kutta tables (ARKStep, fe = f, fi = NULL) at a fixed step, behind the
// Integrator interface: a library of independently written methods of orders 2–8 for the harness
// to tell apart, next to our own fixed-step family (runge_kutta.hpp).
//
// advance() takes exactly `steps` steps of dt from t0: each step is one ARKStepEvolve in
// ARK_ONE_STEP mode with the stop time at t0 + (n+1)·dt, so step n starts at t0 + n·dt exactly
// (no accumulated t += dt) and the last one lands on t0 + steps·dt. The step count is checked
// against ARKStepGetNumSteps.
// name() "arkode-erk:<TABLE>", order() the table's method order q.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/sundials/cvode_integrator.hpp"
#include "dlpverify/butcher_method.hpp"
#include "dlpverify/integrator.hpp"

namespace dlpverify {

struct ArkodeTableInfo {
  std::string name;  // e.g. "ARKODE_HEUN_EULER_2_1_2" (stages_embedding-order_order)
  int stages;
  int order;            // q, the method order
  int embedding_order;  // p, 0 when the table has no embedding
};

// The ERK tables of this SUNDIALS (6.4.1: 15 tables, ARKODE_HEUN_EULER_2_1_2 … ARKODE_FEHLBERG_13_7_8).
const std::vector<ArkodeTableInfo>& arkode_erk_tables();

class ArkodeErkIntegrator final : public Integrator, public ButcherMethod {
 public:
  // Throws InputError("integrator", "arkode-erk:" + table, "unknown ARKODE table") for a name
  // not in arkode_erk_tables(). `across_ranks`: as CvodeSettings::across_ranks.
  explicit ArkodeErkIntegrator(const std::string& table, bool openmp_vector = false, bool across_ranks = false);
  ~ArkodeErkIntegrator() override;
  ArkodeErkIntegrator(ArkodeErkIntegrator&&) noexcept;
  ArkodeErkIntegrator& operator=(ArkodeErkIntegrator&&) noexcept;

  std::string name() const override { return "arkode-erk:" + table_.name; }
  int order() const override { return table_.order; }
  const ArkodeTableInfo& table() const { return table_; }
  // Throws SolverError when ARKODE fails or does not take exactly `steps` steps.
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override;
  // Of the last advance(): steps, rhs_evals, table, order.
  SolverStatistics statistics() const override;
  // The table's A, b and c as ARKODE holds them: a study in extended precision steps them itself
  // (dlpverify/extended_study.hpp).
  ButcherCoefficients butcher() const override;

 private:
  struct Solver;  // the SUNDIALS objects, kept across advance() calls of the same cloud size
  ArkodeTableInfo table_;
  bool openmp_vector_;
  bool across_ranks_;
  std::unique_ptr<Solver> solver_;
  SolverStatistics statistics_;
};

// "cvode" → CvodeIntegrator(settings); "arkode-erk:<TABLE>" → ArkodeErkIntegrator(TABLE,
// settings.openmp_vector, settings.across_ranks). Anything else: InputError naming the integrator.
std::unique_ptr<Integrator> make_sundials_integrator(const std::string& name, const CvodeSettings& settings = {});

}  // namespace dlpverify
