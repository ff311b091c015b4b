// A problem's right-hand side over a whole population (N × F states), for the implicit schemes,
// which iterate on every member's state at once.
#pragma once

#include "dlpverify/problem.hpp"

namespace dlpverify::implicit {

// dydt = f(t, y) for every member, in blocks of members (threads take blocks).
void population_rhs(const Problem& problem, double t, const State& y, State& dydt);

// λ of Problem::linear_decay for every member (N × F), or an empty array when the problem
// separates no linear decay.
State population_linear_decay(const Problem& problem);

}  // namespace dlpverify::implicit
