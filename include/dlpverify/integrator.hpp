/// @file
/// What the convergence harness needs of a time integrator, and nothing more.
///
/// In the spirit of Boost.Odeint's stepper concept: a name, a nominal order, and "advance the
/// state of a problem from t0 by `steps` steps of dt". The problem is a parameter, not a fixed
/// class, so one integrator serves every problem. The harness calls advance() once per level:
/// the one virtual call is per study level, never per member or per step.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>

#include "dlpverify/errors.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/solver_statistics.hpp"

namespace dlpverify {

/// What every advance() refuses before any work: a time step that is not positive and finite
/// (InputError naming "time step"), a negative step count ("step count"). Zero steps are no work.
inline void check_step(double dt, long steps) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    char text[32];  // the shortest %g text that reads back to dt
    for (int digits = 1; digits <= 17; ++digits) {
      std::snprintf(text, sizeof text, "%.*g", digits, dt);
      if (std::strtod(text, nullptr) == dt || digits == 17) break;
    }
    throw InputError("time step", text, "must be positive and finite");
  }
  if (steps < 0) throw InputError("step count", std::to_string(steps), "must be non-negative");
}

/// A time integrator under test: a name, a nominal order and advance(); one instance serves every problem.
class Integrator {
 public:
  virtual ~Integrator() = default;
  /// The name reports give it, e.g. "rk2".
  virtual std::string name() const = 0;
  /// Nominal order of accuracy; 0 for a variable-order method.
  virtual int order() const = 0;
  /// Advance every member of `state` (the problem's N × F layout) from t0 to t0 + steps·dt.
  /// Step n starts at t0 + n·dt (never t += dt). A variable-step method takes dt as its largest step.
  /// Calls check_step(dt, steps) first; zero steps leave `state` as it was, bit for bit.
  virtual void advance(const Problem& problem, State& state, double t0, double dt, long steps) = 0;
  /// Solver statistics of the last advance() (steps, RHS evaluations, …); every count unreported
  /// (SolverStatistics::empty()) when the integrator keeps none.
  virtual SolverStatistics statistics() const { return {}; }
};

/// How an integrator steps a population, which decides whether a study may run it on more than
/// one rank (docs/mpi.md): each member alone, so a rank's share takes the serial run's bits (the
/// Runge–Kutta methods); the whole population in vectors whose sums span every rank (CVODE and
/// ARKODE over CvodeSettings::across_ranks); or the whole population at once, on one rank only.
enum class IntegratorReach { each_member, across_ranks, whole_population };

/// Makes the integrator for the members a rank solves (the whole problem on one rank): CVODE's
/// absolute tolerances, for one, are per member.
using MakeIntegrator = std::function<std::unique_ptr<Integrator>(const Problem& share)>;

}  // namespace dlpverify
