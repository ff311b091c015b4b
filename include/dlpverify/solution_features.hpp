/// @file
/// What a problem may know of its solution's shape, for the references and the audit of closed
/// forms: where a member's solution has a kink, and over what time it changes. Capabilities
/// (problem.hpp); without them a reference never restarts and a time scale is estimated from f.
#pragma once

#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// Each member's time of a kink in its solution: a point where it is only once differentiable
/// (a particle's apex under drag and gravity). A tight reference restarts there, and an
/// ODE-residual stencil that straddles one is skipped.
class SolutionKinks : public Capability {
 public:
  /// For members first … first + initial.rows() − 1 from `initial` at t0: the time after t0 of
  /// each one's kink, NaN when it has none.
  virtual std::vector<double> kink_times(Eigen::Index first, const State& initial) const = 0;
};

/// The time over which a member's state changes appreciably (its fastest rate's time scale).
class TimeScale : public Capability {
 public:
  /// Member `member`, whose F fields are y[0 … F), at t0 + tau; +∞ when nothing limits it.
  virtual double time_scale(Eigen::Index member, const double* y, double tau) const = 0;
};

/// SolutionKinks of `problem` for the whole population, or NaN for every member.
std::vector<double> kink_times(const Problem& problem, const State& initial);
/// TimeScale of `problem`, or the shortest |y_f / f_f(t, y)| over the member's fields (|tau|, or 1,
/// where no field changes).
double time_scale(const Problem& problem, Eigen::Index member, const double* y, double tau);

}  // namespace dlpverify
