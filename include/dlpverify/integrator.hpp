// What the convergence harness needs of a time integrator, and nothing more.
//
// In the spirit of Boost.Odeint's stepper concept: a name, a nominal order, and "advance the
// state of a problem from t0 by `steps` steps of dt". The problem is a parameter, not a fixed
// class, so one integrator serves every problem. The harness calls advance() once per level:
// the one virtual call is per study level, never per member or per step.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/problem.hpp"

namespace dlpverify {

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  // Nominal order of accuracy; 0 for a variable-order method.
  virtual int order() const = 0;
  // Advance every member of `state` (the problem's N × F layout) from t0 to t0 + steps·dt.
  // Step n starts at t0 + n·dt (never t += dt). A variable-step method takes dt as its largest step.
  virtual void advance(const Problem& problem, State& state, double t0, double dt, long steps) = 0;
  // Solver statistics of the last advance() (steps, RHS evaluations, …), empty when there are none.
  virtual nlohmann::json statistics() const { return nlohmann::json::object(); }
};

}  // namespace dlpverify
