/// @file
/// How the implicit and staggered solvers may split a problem: blocks of fields solved together,
/// and a linear decay treated exactly. Capabilities (problem.hpp); without them every field is a
/// block of its own and nothing is treated exactly.
#pragma once

#include <string>
#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// Consecutive fields a staggered solver solves together while it holds the others frozen
/// (docs/model.md §7.3), e.g. a second-order equation's value and rate.
struct FieldBlock {
  std::string name;     ///< for messages
  int first_field = 0;  ///< index of its first field
  int fields = 1;       ///< number of consecutive fields in the block
};

/// The blocks a staggered solver iterates over, in its order (Gauss–Seidel uses each block's new
/// values in the next).
class StaggeredBlocks : public Capability {
 public:
  /// The blocks, covering every field once.
  virtual std::vector<FieldBlock> staggered_blocks() const = 0;
};

/// The spectral radius of a staggered sweep in closed form (docs/model.md §7.3), which the measured
/// contraction of a backward-Euler step is held to: a problem whose coupling is linear and known.
class SweepContraction : public Capability {
 public:
  /// ρ of a Jacobi sweep at step dt.
  virtual double jacobi_radius(double dt) const = 0;
  /// ρ of a Gauss–Seidel sweep at step dt.
  virtual double gauss_seidel_radius(double dt) const = 0;
  /// Jacobi's ρ as a formula, for reports ("dt/sqrt(ab)").
  virtual std::string jacobi_radius_formula() const = 0;
  /// Gauss–Seidel's ρ as a formula, for reports ("dt^2/(ab)").
  virtual std::string gauss_seidel_radius_formula() const = 0;
  /// The largest step at which the sweeps converge (ρ < 1).
  virtual double step_limit() const = 0;
  /// The step limit as a formula ("sqrt(ab)").
  virtual std::string step_limit_formula() const = 0;
  /// The exponent p of ρ ∝ dt^p, by which an adaptive sweep scales its step.
  virtual double radius_exponent() const = 0;
};

/// A linear decay an implicit fixed-point iteration treats exactly: f(y) = −λ∘y + g(y), with
/// λ ≥ 0 constant per member and field (an implicit cooling update keeps convection in its
/// denominator).
class LinearDecay : public Capability {
 public:
  /// Writes λ of the members first … first + count − 1 (lambda[f][i]).
  virtual void linear_decay(Eigen::Index first, int count, double* const* lambda) const = 0;
};

/// StaggeredBlocks of `problem`, or each field a block of its own.
std::vector<FieldBlock> staggered_blocks(const Problem& problem);

}  // namespace dlpverify
