#include "integrators/implicit/staggered_solver.hpp"

#include <cmath>

#include "integrators/implicit/member_norms.hpp"
#include "integrators/implicit/population_rhs.hpp"

namespace dlpverify::implicit {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr int kBlockPasses = 200;

}  // namespace

std::string sweep_name(Sweep sweep) { return sweep == Sweep::jacobi ? "jacobi" : "gauss-seidel"; }

StaggeredSolver::StaggeredSolver(const Problem& problem, Sweep sweep, const State& sizes)
    : problem_(problem), sweep_(sweep), blocks_(staggered_blocks(problem)), size_(field_scales(problem, sizes)) {
  const int count = static_cast<int>(blocks_.size());
  window_ = count % 2 == 0 ? count : 2 * count;
}

// z ← y_b + Δt f_b(t1, [z, others frozen]) until z stops changing (to a few ulps of its size).
bool StaggeredSolver::solve_block(const FieldBlock& block, const State& y, double t1, double dt, State& trial,
                                  long& passes) {
  for (int pass = 0; pass < kBlockPasses; ++pass) {
    evaluate_rhs(problem_, t1, trial, rate_);
    ++passes;
    double change = 0.0, size = 0.0;
    for (int f = block.first_field; f < block.first_field + block.fields; ++f) {
      const Eigen::ArrayXd next = y.col(f) + dt * rate_.col(f);
      change = std::max(change, ((next - trial.col(f)).abs() / size_[static_cast<std::size_t>(f)]).maxCoeff());
      size = std::max(size, (next.abs() / size_[static_cast<std::size_t>(f)]).maxCoeff());
      trial.col(f) = next;
    }
    if (!std::isfinite(change)) return false;
    if (change <= 4.0 * kEpsilon * std::max(size, 1.0)) return true;
  }
  return false;
}

StaggeredIteration StaggeredSolver::step(const State& y, double t, double dt, const std::vector<double>& tolerance,
                                         int max_sweeps, State& w) {
  const double t1 = t + dt;
  StaggeredIteration it;
  std::vector<double> corrections;  // ‖δ^K‖, K = 1, 2, …
  w = y;                            // w^0 = y
  while (it.sweeps < max_sweeps) {
    previous_ = w;
    trial_ = w;
    bool solved = true;
    for (const FieldBlock& block : blocks_) {
      if (sweep_ == Sweep::jacobi) trial_ = previous_;  // every other block at the previous sweep's values
      if (!solve_block(block, y, t1, dt, trial_, it.block_solves) && solved) {
        solved = false;
        it.failed_block = block.name;
      }
      for (int f = block.first_field; f < block.first_field + block.fields; ++f) w.col(f) = trial_.col(f);
    }
    ++it.sweeps;
    corrections.push_back(member_norms(w, previous_, size_, 0, static_cast<int>(w.cols())).matrix().norm());
    it.errors.clear();
    bool all_within = true;
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      const FieldBlock& block = blocks_[b];
      const double moved = member_norms(w, previous_, size_, block.first_field, block.fields).sum();
      const double step_change = member_norms(w, y, size_, block.first_field, block.fields).sum();
      const double error = moved == 0.0 ? 0.0 : moved / step_change;
      it.errors.push_back(error);
      const bool at_round_off = moved <= 4.0 * kEpsilon * member_norms(w, size_, block.first_field, block.fields).sum();
      all_within = all_within && (error <= tolerance[b] || at_round_off);
    }
    if (it.sweeps == 1) it.first_errors = it.errors;
    const std::size_t k = corrections.size();
    if (k == static_cast<std::size_t>(window_) + 2 && corrections[1] > 0.0)
      it.contraction = std::pow(corrections[k - 1] / corrections[1], 1.0 / window_);
    if (!solved || !std::isfinite(corrections.back())) {
      it.diverged = true;
      return it;
    }
    if (all_within) {
      it.converged = true;
      return it;
    }
    if (k >= static_cast<std::size_t>(window_) + 2 && corrections[k - 1] >= corrections[k - 1 - window_]) {
      it.diverged = true;
      return it;
    }
  }
  return it;
}

}  // namespace dlpverify::implicit
