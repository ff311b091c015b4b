#include "integrators/implicit/adaptive.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dlpverify/errors.hpp"
#include "integrators/implicit/member_norms.hpp"
#include "integrators/implicit/population_rhs.hpp"

namespace dlpverify::implicit {

namespace {

constexpr double kLeast = 0.1, kMost = 10.0;  // Φ's bounds (ours)

// Φ_K of eq. 7.38, the smallest over blocks; a block with no correction left allows any growth.
double step_factor(const StaggeredIteration& it, const AdaptiveSettings& s) {
  double phi = kMost;
  const double p = s.exponent;
  for (std::size_t b = 0; b < it.errors.size(); ++b) {
    const double e0 = it.first_errors[b], e = it.errors[b];
    if (!(e > 0.0) || !(e0 > 0.0)) continue;
    const double aim = std::pow(s.tolerance[b] / e0, 1.0 / (p * s.target_sweeps));
    const double now = std::pow(e / e0, 1.0 / (p * it.sweeps));
    phi = std::min(phi, aim / now);
  }
  if (it.diverged || std::isnan(phi)) phi = std::min(phi, 0.5);  // a diverged iteration always shrinks
  return std::clamp(phi, kLeast, kMost);
}

// ½ Δt ‖f(t1, w) − f(t, y)‖ per member relative to ‖w‖, the largest over members (sizes weighed).
double local_error(const State& rate_start, const State& rate_end, const State& w, double dt,
                   const std::vector<double>& size) {
  const int fields = static_cast<int>(w.cols());
  return (0.5 * dt * member_norms(rate_end, rate_start, size, 0, fields) / member_norms(w, size, 0, fields).max(1e-300))
      .maxCoeff();
}

}  // namespace

AdaptiveRun run_adaptive(const Problem& problem, const State& initial, double t0, double t_end, double dt_start,
                         const AdaptiveSettings& s) {
  StaggeredSolver solver(problem, s.sweep, initial);
  const std::vector<double> size = field_scales(problem, initial);
  const bool error_control = !std::isnan(s.error_tolerance);
  const double duration = t_end - t0;
  AdaptiveRun run;
  run.state = initial;
  State next, rate_start, rate_end;
  double t = t0, dt = dt_start;  // the first step as given, even above Δt_lim (the document bounds only the steps it makes)
  while (t < t_end) {
    const bool last = t + dt >= t_end;
    const double h = last ? t_end - t : dt;
    if (h < 1e-14 * duration) {
      char line[200];
      std::snprintf(line, sizeof line, "stagger: the adaptive step fell to %.3g s at t = %.6g s; the run cannot go on", h, t);
      throw SolverError(line);
    }
    const StaggeredIteration it = solver.step(run.state, t, h, s.tolerance, s.target_sweeps, next);
    run.sweeps += it.sweeps;
    double phi = step_factor(it, s);
    if (!it.converged) {  // (6): restart at t with Φ Δt
      ++run.rejected_staggering;
      dt = std::min(phi, 0.9) * h;
      continue;
    }
    if (error_control) {
      evaluate_rhs(problem, t, run.state, rate_start);
      evaluate_rhs(problem, t + h, next, rate_end);
      const double error = local_error(rate_start, rate_end, next, h, size);
      const double allowed = s.error_tolerance * h / duration;
      const double fit = error > 0.0 ? 0.9 * std::sqrt(allowed / error) : kMost;  // local error ∝ Δt²
      if (error > allowed) {
        ++run.rejected_error;
        dt = std::clamp(fit, kLeast, 0.9) * h;
        continue;
      }
      phi = std::min(phi, std::clamp(fit, kLeast, kMost));
    }
    // (5): accept, then Φ Δt, at most Δt_lim
    t = last ? t_end : t + h;
    run.state.swap(next);
    ++run.accepted;
    if (run.accepted == 1) run.first_step = h;
    run.largest_step = std::max(run.largest_step, h);
    if (!last) run.smallest_step = std::min(run.smallest_step, h);
    dt = std::min(phi * h, s.dt_max);
  }
  if (!std::isfinite(run.smallest_step)) run.smallest_step = run.largest_step;
  return run;
}

}  // namespace dlpverify::implicit
