// What the implicit schemes need of a problem over a whole population (N × F states): its
// right-hand side (dlpverify/evaluate_rhs.hpp) and its linear decay.
#pragma once

#include "dlpverify/evaluate_rhs.hpp"
#include "dlpverify/problem.hpp"

namespace dlpverify::implicit {

// λ of the LinearDecay capability (dlpverify/splitting.hpp) for every member (N × F), or an empty array when the problem
// separates no linear decay.
State population_linear_decay(const Problem& problem);

}  // namespace dlpverify::implicit
