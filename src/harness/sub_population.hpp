// Members first … first + count − 1 of a problem, as a problem of their own: a solver that
// works on a block of the population (the CVODE reference does) hands the problem the members'
// own indices, so a problem with per-member parameters sees the right ones.
#pragma once

#include "dlpverify/problem.hpp"

namespace dlpverify {

class SubPopulation final : public Problem {
 public:
  SubPopulation(const Problem& whole, Eigen::Index first, Eigen::Index count)
      : whole_(whole), first_(first), count_(count) {}

  std::string name() const override { return whole_.name(); }
  std::vector<Field> fields() const override { return whole_.fields(); }
  std::vector<Variable> variables() const override { return whole_.variables(); }
  Eigen::Index members() const override { return count_; }
  double initial_time() const override { return whole_.initial_time(); }
  State initial_state() const override { return whole_.initial_state().middleRows(first_, count_); }
  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    whole_.rhs(t, first_ + first, count, y, dydt);
  }

 private:
  const Problem& whole_;
  Eigen::Index first_, count_;
};

}  // namespace dlpverify
