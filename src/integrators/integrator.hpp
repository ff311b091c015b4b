// What the convergence harness needs of a time integrator, and nothing more.
//
// In the spirit of Boost.Odeint's stepper concept: a name, a nominal order, and "advance the
// cloud from t0 by `steps` steps of dt". The harness calls advance() once per level, so the one
// virtual call is per study level, never per particle or per step.
#pragma once

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "problems/dlp/cloud.hpp"
#include "problems/dlp/rates.hpp"

namespace dlpverify {

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  // Nominal order of accuracy; 0 for a variable-order method.
  virtual int order() const = 0;
  // Advance every particle from t0 to t0 + steps·dt. Step n starts at t0 + n·dt (never t += dt).
  virtual void advance(const ParticleRates& rates, Cloud& cloud, double t0, double dt, long steps) = 0;
  // Solver statistics of the last advance() (steps, RHS evaluations, …), empty when there are none.
  virtual nlohmann::json statistics() const { return nlohmann::json::object(); }
};

}  // namespace dlpverify
