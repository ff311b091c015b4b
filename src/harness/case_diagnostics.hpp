// A case's diagnostics reduced over the population in fixed blocks (the norms' blocks,
// harness/compensated_sum.hpp), so that each process reduces its own members and the blocks'
// partials, combined in global block order, give the serial run's bits on any number of
// processes and threads.
#pragma once

#include <vector>

#include "dlpverify/case_report.hpp"

namespace dlpverify {

// Doubles per quantity in a block's partial: a sum's rounded sum and its compensation (NeumaierSum),
// a minimum's or a maximum's value and 0.
inline constexpr std::size_t kDiagnosticPartialDoubles = 2;

// The block partials of `report`'s quantities over members first … first + initial.rows() − 1
// (CaseReport::member_terms), block after block in member order. A share of whole blocks from a
// global block boundary (harness/distribution.hpp) gives the whole's partials of those blocks.
std::vector<double> diagnostic_partials(const CaseReport& report, Eigen::Index first, const State& initial,
                                        const State& finest, double t_end);

// The quantities reduced from every block's partials, taken in block order.
std::vector<double> reduced_diagnostics(const std::vector<MemberReduction>& reductions,
                                        const std::vector<double>& partials);

}  // namespace dlpverify
