// Steppers written in this project, as a user writes them: dlpverify sees them only through
// dlpverify::Integrator, and hands them any problem's block right-hand side.
#pragma once

#include <vector>

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
      rhs(problem, t, y, k1);
      half = y + stage * k1;
      rhs(problem, t + 0.5 * dt, half, k2);
      y += dt * k2;
    }
  }

 private:
  // f(t, y) of every member, handed to the problem as one block in structure-of-arrays form.
  static void rhs(const dlpverify::Problem& problem, double t, const dlpverify::State& y, dlpverify::State& dydt) {
    std::vector<const double*> in(static_cast<std::size_t>(y.cols()));
    std::vector<double*> out(static_cast<std::size_t>(y.cols()));
    for (Eigen::Index f = 0; f < y.cols(); ++f) {
      in[static_cast<std::size_t>(f)] = y.col(f).data();
      out[static_cast<std::size_t>(f)] = dydt.col(f).data();
    }
    problem.rhs(t, 0, static_cast<int>(y.rows()), in.data(), out.data());
  }
  bool broken_;
};
