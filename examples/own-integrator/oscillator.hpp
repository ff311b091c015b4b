// A problem dlpverify does not ship: N damped harmonic oscillators, x'' + 2ζω x' + ω² x = 0,
// as the first-order system (x, v)' = (v, −2ζω v − ω² x), each member with its own ω.
//
// Closed form (underdamped, ζ < 1), with ω_d = ω √(1 − ζ²) and σ = ζω:
//   x(τ) = e^(−στ) [x0 cos ω_d τ + (v0 + σ x0)/ω_d sin ω_d τ]
//   v(τ) = e^(−στ) [v0 cos ω_d τ − (σ v0 + ω² x0)/ω_d sin ω_d τ]
#pragma once

#include <cmath>

#include <dlpverify/closed_form.hpp>
#include <dlpverify/problem.hpp>

// The closed form is a capability: provided from the constructor, found by every reference.
class DampedOscillators final : public dlpverify::Problem, public dlpverify::ClosedForm {
 public:
  explicit DampedOscillators(int members, double damping_ratio = 0.1) : members_(members), zeta_(damping_ratio) {
    provide<dlpverify::ClosedForm>(*this);
  }

  std::string name() const override { return "damped-oscillators"; }
  std::vector<dlpverify::Field> fields() const override { return {{"x", "m"}, {"v", "m/s"}}; }
  std::vector<dlpverify::Variable> variables() const override {
    return {{"displacement", 0, 1, "m"}, {"velocity", 1, 1, "m/s"}};
  }
  Eigen::Index members() const override { return members_; }
  double initial_time() const override { return 0.0; }
  dlpverify::State initial_state() const override {
    dlpverify::State y(members_, 2);
    for (int p = 0; p < members_; ++p) {
      y(p, 0) = 1.0 + 0.01 * p;  // x0 [m]
      y(p, 1) = 0.0;             // v0 [m/s]
    }
    return y;
  }
  // Member p has ω = 1 + p/N rad/s: the block's `first` says which members these are.
  double omega(Eigen::Index p) const { return 1.0 + static_cast<double>(p) / members_; }

  void rhs(double, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) {
      const double w = omega(first + i);
      dydt[0][i] = y[1][i];
      dydt[1][i] = -2.0 * zeta_ * w * y[1][i] - w * w * y[0][i];
    }
  }

  std::string formula() const override { return "x = exp(-sigma t) [x0 cos(wd t) + (v0 + sigma x0)/wd sin(wd t)]"; }
  // Members first … first + initial.rows() − 1 at t0 + tau.
  dlpverify::State solution(Eigen::Index first, const dlpverify::State& initial, double tau) const override {
    dlpverify::State y(initial.rows(), 2);
    for (Eigen::Index p = 0; p < initial.rows(); ++p) {
      const double w = omega(first + p), sigma = zeta_ * w, wd = w * std::sqrt(1.0 - zeta_ * zeta_);
      const double x0 = initial(p, 0), v0 = initial(p, 1), decay = std::exp(-sigma * tau);
      const double c = std::cos(wd * tau), s = std::sin(wd * tau);
      y(p, 0) = decay * (x0 * c + (v0 + sigma * x0) / wd * s);
      y(p, 1) = decay * (v0 * c - (sigma * v0 + w * w * x0) / wd * s);
    }
    return y;
  }

 private:
  int members_;
  double zeta_;
};
