// A problem dlpverify does not ship, with an explicit time in its right-hand side and no closed
// form: N driven, damped pendulums in dimensionless time,
//   θ″ + c θ′ + ω_p² sin θ = F cos(Ω t),
// as the first-order system (θ, ω)′ = (ω, −c ω − ω_p² sin θ + F cos Ω t), each member with its own
// natural frequency ω_p = 1 + p/(2N). Without a closed form it is studied against a manufactured
// reference or against another integrator at a finer step (verify.cpp).
#pragma once

#include <cmath>

#include <dlpverify/case_report.hpp>
#include <dlpverify/problem.hpp>

// Time is dimensionless (a TimeUnit of "1"), so θ and ω = dθ/dt are both in radians.
class ForcedPendulums final : public dlpverify::Problem, public dlpverify::TimeUnit {
 public:
  explicit ForcedPendulums(int members, double damping = 0.1, double forcing = 0.4, double drive_frequency = 2.0 / 3.0)
      : members_(members), c_(damping), force_(forcing), drive_(drive_frequency) {
    provide<dlpverify::TimeUnit>(*this);
  }

  std::string name() const override { return "forced-pendulums"; }
  std::vector<dlpverify::Field> fields() const override { return {{"theta", "rad"}, {"omega", "rad"}}; }
  std::vector<dlpverify::Variable> variables() const override {
    return {{"angle", 0, 1, "rad"}, {"angular-velocity", 1, 1, "rad"}};
  }
  Eigen::Index members() const override { return members_; }
  double initial_time() const override { return 0.0; }
  dlpverify::State initial_state() const override {
    dlpverify::State y(members_, 2);
    for (int p = 0; p < members_; ++p) {
      y(p, 0) = 1.0 + 0.01 * p;  // θ0 [rad]: large enough that sin θ is far from θ
      y(p, 1) = 0.0;             // ω0 [rad]
    }
    return y;
  }
  // Member p has ω_p = 1 + p/(2N): the block's `first` says which members these are.
  double natural_frequency(Eigen::Index p) const { return 1.0 + 0.5 * static_cast<double>(p) / members_; }

  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    const double drive = force_ * std::cos(drive_ * t);
    for (int i = 0; i < count; ++i) {
      const double w = natural_frequency(first + i);
      dydt[0][i] = y[1][i];
      dydt[1][i] = -c_ * y[1][i] - w * w * std::sin(y[0][i]) + drive;
    }
  }

  std::string time_unit() const override { return "1"; }

 private:
  int members_;
  double c_;       // damping c
  double force_;   // forcing amplitude F
  double drive_;   // drive frequency Ω
};
