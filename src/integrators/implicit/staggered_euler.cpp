#include "integrators/implicit/staggered_euler.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dlpverify/errors.hpp"
#include "dlpverify/level_stop.hpp"

namespace dlpverify::implicit {

std::string stagger_failure(const std::string& who, const StaggeredIteration& it, double t, double dt) {
  char line[400];
  if (!it.failed_block.empty())  // no sweep to measure: a block's own solve failed first
    std::snprintf(line, sizeof line,
                  "%s: at t = %.6g s, dt = %.6g s the backward-Euler solve of block %s does not settle in sweep %d: "
                  "its fixed-point iteration converges only while dt |df/dy| < 1, so take a smaller step",
                  who.c_str(), t, dt, it.failed_block.c_str(), it.sweeps);
  else if (it.diverged)
    std::snprintf(line, sizeof line,
                  "%s: the staggered iteration diverges at t = %.6g s, dt = %.6g s: its corrections stopped shrinking "
                  "after %d sweeps (measured contraction %.6g per sweep); dt is above the coupling's limit, take a "
                  "smaller step",
                  who.c_str(), t, dt, it.sweeps, it.contraction);
  else
    std::snprintf(line, sizeof line,
                  "%s: the staggered iteration at t = %.6g s, dt = %.6g s did not converge in %d sweeps (measured "
                  "contraction %.6g per sweep); take a smaller step",
                  who.c_str(), t, dt, it.sweeps, it.contraction);
  return line;
}

void StaggeredEuler::advance(const Problem& problem, State& state, double t0, double dt, long steps) {
  check_step(dt, steps);
  StaggeredSolver solver(problem, sweep_, state);
  const std::vector<double> tolerance(solver.blocks().size(), kTolerance);
  State next;
  long sweeps = 0, passes = 0;
  int most = 0;
  double lowest = INFINITY, highest = 0.0;
  for (long n = 0; n < steps; ++n) {
    abandon_level_if_stop_requested();
    const double t = t0 + static_cast<double>(n) * dt;
    const StaggeredIteration it = solver.step(state, t, dt, tolerance, kMaxSweeps, next);
    if (!it.converged) throw SolverError(stagger_failure(name(), it, t, dt));
    state.swap(next);
    sweeps += it.sweeps;
    passes += it.block_solves;
    most = std::max(most, it.sweeps);
    if (std::isfinite(it.contraction)) {
      lowest = std::min(lowest, it.contraction);
      highest = std::max(highest, it.contraction);
    }
  }
  statistics_ = SolverStatistics{};
  statistics_.steps = steps;
  statistics_.rhs_evals = passes;
  statistics_.extras = {{"sweeps", static_cast<long>(sweeps)},
                        {"sweeps_per_step_max", static_cast<long>(most)},
                        {"block_passes", static_cast<long>(passes)},
                        {"contraction_min", std::isfinite(lowest) ? StatisticValue(lowest) : StatisticValue()},
                        {"contraction_max", highest > 0.0 ? StatisticValue(highest) : StatisticValue()}};
}

}  // namespace dlpverify::implicit
