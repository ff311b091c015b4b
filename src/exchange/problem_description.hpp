// The description an exchange file carries (docs/exchange.md): the problem's own
// (ExchangeDescription, dlpverify/exchange_description.hpp) or one made from its report.
#pragma once

#include "dlpverify/exchange_description.hpp"
#include "dlpverify/problem.hpp"

namespace dlpverify {

// ExchangeDescription of `problem`, or by default: "problem", the numbers of CaseReport's
// parameters without units, and its strings as settings.
ProblemDescription problem_description(const Problem& problem);

}  // namespace dlpverify
