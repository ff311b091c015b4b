// The seed's Algorithm 7.1 (docs/model.md §7.3): backward Euler by staggering, with the step
// adapted from the iteration itself. After sweep K of a step, with ε_b the block's normalized
// correction (eq. 7.36) and ε_b0 its value after the first sweep,
//   Z_K = max_b ε_b / TOL_b                                    (eq. 7.37)
//   Φ_K = min_b (TOL_b/ε_b0)^{1/(p K_d)} / (ε_b/ε_b0)^{1/(p K)}  (eq. 7.38)
// where K_d is the sweep count aimed at and p the exponent of the spectral radius's growth with
// the step (ρ ∝ Δt^p: 1 for the 2 × 2 system, 4/3 for the 3 × 3). A step whose Z_K ≤ 1 within K_d
// sweeps is accepted and the next step is Φ_K Δt, at most Δt_lim; a step that has not met its
// tolerances after K_d sweeps restarts with Φ_K Δt.
//
// Ours, beyond the document: Δt_lim may also follow backward Euler's local error, estimated as
// ½ Δt ‖f(t + Δt, y_{n+1}) − f(t, y_n)‖ relative to the member's size and held below
// tol · Δt / duration, so that the requested tolerance bounds the error at the end (the document
// leaves Δt_lim to the user). Φ is kept within [1/10, 10]: the document's Φ is unbounded when a
// block's correction vanishes exactly.
#pragma once

#include <limits>
#include <vector>

#include "dlpverify/problem.hpp"
#include "integrators/implicit/staggered_solver.hpp"

namespace dlpverify::implicit {

struct AdaptiveSettings {
  Sweep sweep = Sweep::gauss_seidel;  // the document's implementation
  int target_sweeps = 10;             // K_d
  std::vector<double> tolerance;      // TOL_b per block
  double exponent = 1.0;              // p
  double dt_max = std::numeric_limits<double>::infinity();  // Δt_lim
  double error_tolerance = std::numeric_limits<double>::quiet_NaN();  // NaN: the document's control alone
};

// The document's Table 7.1 columns and what the run did.
struct AdaptiveRun {
  State state;
  long accepted = 0;
  long rejected_staggering = 0;  // restarted: tolerance not met in K_d sweeps, or diverged
  long rejected_error = 0;       // restarted: local error above its bound
  long sweeps = 0;               // every sweep, rejected steps' too
  double largest_step = 0.0;     // accepted
  double smallest_step = std::numeric_limits<double>::infinity();
  double first_step = 0.0;       // the first accepted
};

// Integrates from `initial` at t0 to t_end, starting with dt_start. Throws SolverError when the step
// falls below 1e-14 of the duration.
AdaptiveRun run_adaptive(const Problem& problem, const State& initial, double t0, double t_end, double dt_start,
                         const AdaptiveSettings& settings);

}  // namespace dlpverify::implicit
