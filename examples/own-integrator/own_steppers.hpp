// Steppers written in this project, as a user writes them: dlpverify sees them only through
// dlpverify::Integrator, and hands them any problem's block right-hand side (evaluate_rhs calls it
// over the whole population).
#pragma once

#include <dlpverify/evaluate_rhs.hpp>
#include <dlpverify/integrator.hpp>

// Explicit midpoint, y½ = y + (Δt/2) f(t, y), y' = y + Δt f(t + Δt/2, y½), on the whole population
// at once (the simplest way a user would write it). With `broken`, the stage is taken at the full
// step, y½ = y + Δt f(t, y): a slip that makes the method first order.
class OwnMidpoint final : public dlpverify::Integrator {
 public:
  explicit OwnMidpoint(bool broken = false) : broken_(broken) {}
  std::string name() const override { return broken_ ? "own-midpoint-broken" : "own-midpoint"; }
  int order() const override { return 2; }

  void advance(const dlpverify::Problem& problem, dlpverify::State& y, double t0, double dt, long steps) override {
    dlpverify::check_step(dt, steps);
    dlpverify::State k1(y.rows(), y.cols()), half(y.rows(), y.cols()), k2(y.rows(), y.cols());
    const double stage = broken_ ? dt : 0.5 * dt;
    for (long n = 0; n < steps; ++n) {
      const double t = t0 + static_cast<double>(n) * dt;
      dlpverify::evaluate_rhs(problem, t, y, k1);
      half = y + stage * k1;
      dlpverify::evaluate_rhs(problem, t + 0.5 * dt, half, k2);
      y += dt * k2;
    }
  }

 private:
  bool broken_;
};
