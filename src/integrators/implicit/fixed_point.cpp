#include "integrators/implicit/fixed_point.hpp"

#include <cmath>
#include <cstdio>

#include "dlpverify/errors.hpp"
#include "dlpverify/level_stop.hpp"
#include "integrators/implicit/population_rhs.hpp"

namespace dlpverify::implicit {

namespace {

// The largest |next − current| over members, each field in units of its size.
double largest_correction(const State& next, const State& current, const Eigen::ArrayXd& scale) {
  double largest = 0.0;
  for (Eigen::Index f = 0; f < next.cols(); ++f) {
    const double c = (next.col(f) - current.col(f)).abs().maxCoeff() / scale(f);
    if (!(c <= largest)) largest = c;  // NaN wins: a non-finite iterate is never converged
  }
  return largest;
}

[[noreturn]] void fail(long step, double t, double dt, int iterations, double correction, double previous,
                       const FixedPointSettings& s) {
  char line[400];
  if (!std::isfinite(correction)) {
    std::snprintf(line, sizeof line,
                  "implicit-fp: the fixed-point iteration of step %ld (t = %.6g s, dt = %.6g s) diverges: its iterate "
                  "became non-finite after %d iterations; it converges only while dt |df/dy| < 1, so take a smaller step",
                  step + 1, t, dt, iterations);
    throw SolverError(line);
  }
  std::snprintf(line, sizeof line,
                "implicit-fp: the fixed-point iteration of step %ld (t = %.6g s, dt = %.6g s) did not converge in %d "
                "iterations: last correction %.3g of the field's size (tolerance %.3g), shrinking by %.3g per "
                "iteration; it converges only while dt |df/dy| < 1, so take a smaller step",
                step + 1, t, dt, iterations, correction, s.tolerance, correction / previous);
  throw SolverError(line);
}

}  // namespace

void FixedPointEuler::advance(const Problem& problem, State& state, double t0, double dt, long steps) {
  check_step(dt, steps);
  const std::vector<double> sizes = field_scales(problem, state);
  const Eigen::ArrayXd scale = Eigen::Map<const Eigen::ArrayXd>(sizes.data(), static_cast<Eigen::Index>(sizes.size()));
  const State lambda = population_linear_decay(problem);
  const bool split = lambda.size() > 0;
  const State denominator = split ? State(1.0 + dt * lambda) : State();
  State start, rate, next;
  long iterations = 0;
  int most = 0;
  for (long n = 0; n < steps; ++n) {
    abandon_level_if_stop_requested();
    const double t1 = t0 + static_cast<double>(n + 1) * dt;
    start = state;  // y_n; state holds the iterate, starting from y_n
    double correction = INFINITY, previous = INFINITY;
    int k = 0;
    while (!(correction <= settings_.tolerance)) {
      if (k == settings_.max_iterations) fail(n, t1 - dt, dt, k, correction, previous, settings_);
      evaluate_rhs(problem, t1, state, rate);
      if (split)
        next = (start + dt * (rate + lambda * state)) / denominator;
      else
        next = start + dt * rate;
      previous = correction;
      correction = largest_correction(next, state, scale);
      state.swap(next);
      ++k;
      if (!std::isfinite(correction)) fail(n, t1 - dt, dt, k, correction, previous, settings_);
    }
    iterations += k;
    most = std::max(most, k);
  }
  statistics_ = SolverStatistics{};
  statistics_.steps = steps;
  statistics_.rhs_evals = iterations;  // one whole-population evaluation per fixed-point iteration
  statistics_.extras = {{"iterations", iterations},
                        {"iterations_per_step_max", static_cast<long>(most)},
                        {"iterations_per_step_mean", steps > 0 ? static_cast<double>(iterations) / steps : 0.0},
                        {"tolerance", settings_.tolerance}};
}

}  // namespace dlpverify::implicit
