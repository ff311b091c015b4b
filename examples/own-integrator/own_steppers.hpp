// Steppers written in this project, as a user writes them: dlpverify sees them only through
// dlpverify::Integrator, and hands them any problem's block right-hand side (evaluate_rhs calls it
// over the whole population).
#pragma once

#include <dlpverify/evaluate_rhs.hpp>
#include <dlpverify/integrator.hpp>

// Explicit midpoint, y½ = y + (Δt/2) f(t, y), y' = y + Δt f(t + Δt/2, y½), on the whole population
// at once (the simplest way a user would write it), or with one of two slips:
//  - full_step_stage: the stage state is taken a full step ahead, y½ = y + Δt f(t, y), while it is
//    evaluated at t + Δt/2: the local error gains ½ Δt² (∂f/∂y) f, first order on any
//    problem whose f depends on y;
//  - late_stage_time: the stage state is right but evaluated at t + 0.6 Δt (c₂ = 0.6 ≠ a₂₁ = ½):
//    the local error gains 0.1 Δt² ∂f/∂t, so the method stays second order wherever f has no
//    explicit t (every autonomous problem) and is first order where it has one.
class OwnMidpoint final : public dlpverify::Integrator {
 public:
  enum class Slip { none, full_step_stage, late_stage_time };
  explicit OwnMidpoint(Slip slip = Slip::none) : slip_(slip) {}
  std::string name() const override {
    switch (slip_) {
      case Slip::full_step_stage: return "own-midpoint-broken";
      case Slip::late_stage_time: return "own-midpoint-late-stage";
      default: return "own-midpoint";
    }
  }
  int order() const override { return 2; }

  void advance(const dlpverify::Problem& problem, dlpverify::State& y, double t0, double dt, long steps) override {
    dlpverify::check_step(dt, steps);
    dlpverify::State k1(y.rows(), y.cols()), half(y.rows(), y.cols()), k2(y.rows(), y.cols());
    const double a21 = slip_ == Slip::full_step_stage ? 1.0 : 0.5;
    const double c2 = slip_ == Slip::late_stage_time ? 0.6 : 0.5;
    for (long n = 0; n < steps; ++n) {
      const double t = t0 + static_cast<double>(n) * dt;
      dlpverify::evaluate_rhs(problem, t, y, k1);
      half = y + (a21 * dt) * k1;
      dlpverify::evaluate_rhs(problem, t + c2 * dt, half, k2);
      y += dt * k2;
    }
  }

 private:
  Slip slip_;
};
