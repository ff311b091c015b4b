// One backward-Euler step solved by staggering (docs/model.md §7.3): the fields fall into blocks
// (Problem::staggered_blocks), each block is solved with the others frozen, and the sweep over the
// blocks repeats until the step's fields stop changing. Jacobi freezes every other block at the
// previous sweep's values; Gauss–Seidel uses each block's new values in the blocks after it.
//
// A block with the others frozen is itself solved by fixed-point iteration to round-off (exact in
// one or two passes when the block's rate does not depend on the block, as in the seed's linear
// systems). After each sweep K, block b's normalized correction is the seed's eq. 7.36,
//   ε_b = Σ_i ‖w_{b,i}^K − w_{b,i}^{K−1}‖ / Σ_i ‖w_{b,i}^K − y_{b,i}‖   (sums over members),
// and the step has converged when every ε_b is within its tolerance (or its corrections are at
// round-off). The contraction is measured over W sweeps after the first,
//   ρ̂ = (‖δ^{2+W}‖ / ‖δ^2‖)^{1/W},   δ^K = w^K − w^{K−1} = G δ^{K−1} for a linear coupling,
// with W the blocks' count (twice it when odd). δ^1 starts from the previous step's state, but
// every later δ lies in the range of the sweep's matrix G, where for the cyclic couplings of §7.3
// G^W ∝ I under both sweeps (Gauss–Seidel's G is singular, and a second-order block's rate rides
// along with its value): ρ̂ is then exact, and the asymptotic rate for any other problem.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "dlpverify/splitting.hpp"
#include "dlpverify/problem.hpp"

namespace dlpverify::implicit {

enum class Sweep { jacobi, gauss_seidel };
std::string sweep_name(Sweep sweep);

// What one step's iteration did.
struct StaggeredIteration {
  bool converged = false;
  bool diverged = false;  // corrections stopped shrinking over a window (contraction ≥ 1), or non-finite
  int sweeps = 0;         // K at exit
  std::vector<double> first_errors;  // ε_b after the first sweep (the seed's ε_0)
  std::vector<double> errors;        // ε_b after the last
  double contraction = std::numeric_limits<double>::quiet_NaN();  // ρ̂; NaN: converged within W + 1 sweeps
  long block_solves = 0;  // fixed-point passes of the blocks, all sweeps
  // The block whose own fixed-point solve failed (non-finite, or not settled in its passes), which
  // ends the iteration as diverged; empty when every block's solve settled.
  std::string failed_block;
};

class StaggeredSolver {
 public:
  // `sizes`: the state whose field sizes (field_scales) weigh the fields of one block.
  StaggeredSolver(const Problem& problem, Sweep sweep, const State& sizes);

  // From y at t, the state w at t + dt: sweeps until every block's ε_b ≤ tolerance[b], divergence,
  // or max_sweeps.
  StaggeredIteration step(const State& y, double t, double dt, const std::vector<double>& tolerance, int max_sweeps,
                          State& w);

  const std::vector<FieldBlock>& blocks() const { return blocks_; }
  Sweep sweep() const { return sweep_; }
  int window() const { return window_; }

 private:
  // Solves block b of `trial` (the other blocks frozen in it) at t1; false when it does not converge.
  bool solve_block(const FieldBlock& block, const State& y, double t1, double dt, State& trial, long& passes);

  const Problem& problem_;
  Sweep sweep_;
  std::vector<FieldBlock> blocks_;
  std::vector<double> size_;  // each field's size (field_scales)
  int window_;
  State previous_, trial_, rate_;
};

}  // namespace dlpverify::implicit
