// Test support: y' = −y², y(0) = 1, whose closed form y = 1/(1 + t) is its reference, and whose
// global error for every two-stage method of order 2 and for explicit Euler has a leading constant
// in closed form (test_error_constant.cpp). One member, so the L2 error is |e|. Beside it, the
// linear test equation y' = λy.
#pragma once

#include "dlpverify/closed_form.hpp"
#include "dlpverify/problem.hpp"

namespace dlpverify::test {

class QuadraticDecay final : public Problem, public ClosedForm {
 public:
  QuadraticDecay() { provide<ClosedForm>(*this); }
  std::string name() const override { return "quadratic-decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  std::vector<Variable> variables() const override { return {{"y", 0, 1, "1"}}; }
  Eigen::Index members() const override { return 1; }
  State initial_state() const override { return State::Constant(1, 1, 1.0); }
  void rhs(double, Eigen::Index, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = -y[0][i] * y[0][i];
  }
  std::string formula() const override { return "y0 / (1 + y0 t)"; }
  State solution(Eigen::Index, const State& initial, double tau) const override {
    State y(initial.rows(), 1);
    for (Eigen::Index p = 0; p < initial.rows(); ++p) y(p, 0) = initial(p, 0) / (1.0 + initial(p, 0) * tau);
    return y;
  }
};

// y' = λ y, y(0) = 1, one member: the linear test equation of stability theory.
class LinearDecay final : public Problem {
 public:
  explicit LinearDecay(double lambda) : lambda_(lambda) {}
  std::string name() const override { return "linear-decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  std::vector<Variable> variables() const override { return {{"y", 0, 1, "1"}}; }
  Eigen::Index members() const override { return 1; }
  State initial_state() const override { return State::Constant(1, 1, 1.0); }
  void rhs(double, Eigen::Index, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = lambda_ * y[0][i];
  }

 private:
  double lambda_;
};

}  // namespace dlpverify::test
