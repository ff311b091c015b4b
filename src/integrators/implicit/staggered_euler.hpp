// Backward Euler by staggering at a fixed step, for any problem (docs/model.md §7.3): every step
// iterates the sweeps (staggered_solver.hpp) until each block's normalized correction is below
// 1e-12, so what a study measures is backward Euler's error (order 1), not the staggering's. A
// step whose iteration diverges (Δt above the coupling's limit) or does not converge ends the run
// with a SolverError naming the step and the measured contraction.
#pragma once

#include "dlpverify/integrator.hpp"
#include "integrators/implicit/staggered_solver.hpp"

namespace dlpverify::implicit {

class StaggeredEuler final : public Integrator {
 public:
  explicit StaggeredEuler(Sweep sweep) : sweep_(sweep) {}
  std::string name() const override { return "stagger-" + sweep_name(sweep_); }
  int order() const override { return 1; }
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override;
  SolverStatistics statistics() const override { return statistics_; }

  static constexpr double kTolerance = 1e-12;
  static constexpr int kMaxSweeps = 500;

 private:
  Sweep sweep_;
  SolverStatistics statistics_;
};

// The line a diverged or unconverged step ends with (SolverError's text).
std::string stagger_failure(const std::string& who, const StaggeredIteration& it, double t, double dt);

}  // namespace dlpverify::implicit
