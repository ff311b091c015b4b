// Backward Euler solved by fixed-point iteration: the seed's implicit cooling update (its eq. 7.30
// solved by 7.33, docs/model.md §7.3), for any problem. Each step solves
//   y_{n+1} = y_n + Δt f(t_{n+1}, y_{n+1})
// by iterating, with the linear decay λ a problem separates (f = −λ∘y + g) kept exact,
//   y^K = (y_n + Δt (f(y^{K−1}) + λ∘y^{K−1})) / (1 + Δt λ),
// which for particle cooling is the seed's update: convection in the denominator, radiation
// iterated. It converges while Δt ‖∂g/∂y‖/(1 + Δt λ) < 1. Order 1. Every step's iteration count
// is reported; a step that does not converge ends the run with a SolverError, never quietly.
#pragma once

#include <string>

#include "dlpverify/integrator.hpp"

namespace dlpverify::implicit {

struct FixedPointSettings {
  double tolerance = 1e-12;  // the largest correction |y^K − y^{K−1}|, in units of its field's size
  int max_iterations = 100;
};

class FixedPointEuler final : public Integrator {
 public:
  explicit FixedPointEuler(FixedPointSettings settings = {}) : settings_(settings) {}
  std::string name() const override { return "implicit-fp"; }
  int order() const override { return 1; }
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override;
  SolverStatistics statistics() const override { return statistics_; }

 private:
  FixedPointSettings settings_;
  SolverStatistics statistics_;
};

}  // namespace dlpverify::implicit
