/// @file
/// A problem's right-hand side over its whole population: what an integrator written against
/// whole N × F states (an implicit scheme, a user's own stepper) calls instead of building the
/// block pointer tables of Problem::rhs by hand.
#pragma once

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// Members per call of Problem::rhs made by evaluate_rhs: blocks [b·kRhsBlock, min((b + 1)·kRhsBlock, N)).
inline constexpr Eigen::Index kRhsBlock = 256;

/// rates = f(t, state) for every member: `state` is N × F (N = its rows, F = problem.field_count());
/// `rates` is resized to N × F. Problem::rhs is called once per block of kRhsBlock consecutive
/// members with that block's own first member index and field pointers; the blocks are shared
/// over OpenMP threads (static schedule). Each member's rates come from one call on its own block,
/// so the result is bit-identical for any number of threads. `state` and `rates` must not alias.
void evaluate_rhs(const Problem& problem, double t, const State& state, State& rates);

}  // namespace dlpverify
