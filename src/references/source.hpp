// The reference kinds behind one interface (docs/verification.md, "The reference"): each computes
// the state at t0 + t_end with an estimate of its own error, follows the solution through
// increasing times for error histories, and knows the settings that solve it tighter.
// compute_reference, reference_trajectory and tightened_reference (dlpverify/reference.hpp) ask
// the source of the settings' kind (references/reference.cpp).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "dlpverify/reference.hpp"

namespace dlpverify::references {

class ReferenceSource {
 public:
  virtual ~ReferenceSource() = default;
  // The state at t0 + t_end from `initial`, with its error estimate per variable of `variables`
  // (on Problem::measured of its solves) and what it took.
  virtual Reference compute(const Problem& problem, const State& initial, double t_end,
                            const std::vector<Variable>& variables) const = 0;
  // The state at increasing τ from `initial`; each call continues from the one before.
  virtual std::function<State(double tau)> trajectory(const Problem& problem, const State& initial) const = 0;
  // The settings of the next tighter reference for a study of level ratio `ratio`, or nullopt.
  virtual std::optional<ReferenceSettings> tightened(double ratio) const = 0;
};

// The problem's closed form: `kind` is exact or manufactured (closed_form.cpp).
std::unique_ptr<ReferenceSource> closed_form_source(ReferenceKind kind);
// CVODE Adams at settings.rtol, in blocks of members (cvode.cpp).
std::unique_ptr<ReferenceSource> cvode_source(const ReferenceSettings& settings);
// The ODE in Extended by extrapolation, to ε_Extended (extended.cpp).
std::unique_ptr<ReferenceSource> extended_source();
// settings.integrator at the fixed step settings.dt (integrator.cpp).
std::unique_ptr<ReferenceSource> integrator_source(const ReferenceSettings& settings);

// The state at increasing τ from `initial` at τ = 0, each call continuing from the one before:
// `advance(state, from, to)` takes the state from τ = from to τ = to.
inline std::function<State(double tau)> continued_trajectory(
    const State& initial, std::function<void(State& state, double from, double to)> advance) {
  struct Continued {
    State state;
    double tau = 0.0;
  };
  auto last = std::make_shared<Continued>(Continued{initial, 0.0});
  return [last, advance = std::move(advance)](double tau) {
    if (tau > last->tau) {
      advance(last->state, last->tau, tau);
      last->tau = tau;
    }
    return last->state;
  };
}

// Wall time since `start`, for the references' statistics.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace dlpverify::references
