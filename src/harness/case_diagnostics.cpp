#include "harness/case_diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "harness/compensated_sum.hpp"
#include "harness/distribution.hpp"

namespace dlpverify {

namespace {

// Where a minimum or a maximum starts: the value no member's can fail to replace.
double neutral(MemberReduction r) {
  return r == MemberReduction::min ? std::numeric_limits<double>::infinity()
                                   : -std::numeric_limits<double>::infinity();
}

// The smaller or larger of two, NaN once either is NaN (a broken member is never hidden).
double extreme(MemberReduction r, double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<double>::quiet_NaN();
  return r == MemberReduction::min ? std::min(a, b) : std::max(a, b);
}

}  // namespace

std::vector<double> diagnostic_partials(const CaseReport& report, Eigen::Index first, const State& initial,
                                        const State& finest, double t_end) {
  const std::vector<MemberReduction> reductions = report.diagnostic_reductions();
  if (reductions.empty()) return {};
  const Eigen::ArrayXXd terms = report.member_terms(first, initial, finest, t_end);
  // A block's partial: kDiagnosticPartialDoubles doubles per quantity.
  const std::vector<std::vector<double>> blocks = blocked_partials<std::vector<double>>(
      terms.rows(), [&](Eigen::Index from, Eigen::Index count, std::vector<double>& block) {
        for (std::size_t q = 0; q < reductions.size(); ++q) {
          const auto column = terms.col(static_cast<Eigen::Index>(q)).segment(from, count);
          if (reductions[q] == MemberReduction::sum) {
            NeumaierSum sum;
            for (const double term : column) sum.add(term);
            block.insert(block.end(), {sum.sum, sum.compensation});
          } else {
            double value = neutral(reductions[q]);
            for (const double term : column) value = extreme(reductions[q], value, term);
            block.insert(block.end(), {value, 0.0});
          }
        }
      });
  std::vector<double> partials;
  for (const std::vector<double>& block : blocks) partials.insert(partials.end(), block.begin(), block.end());
  return partials;
}

std::vector<double> reduced_diagnostics(const std::vector<MemberReduction>& reductions,
                                        const std::vector<double>& partials) {
  const std::size_t stride = reductions.size() * kDiagnosticPartialDoubles;
  std::vector<NeumaierSum> sums(reductions.size());
  std::vector<double> extremes;
  for (const MemberReduction r : reductions) extremes.push_back(neutral(r));
  for (std::size_t b = 0; stride > 0 && b + stride <= partials.size(); b += stride)
    for (std::size_t q = 0; q < reductions.size(); ++q) {
      const double* p = &partials[b + q * kDiagnosticPartialDoubles];
      if (reductions[q] == MemberReduction::sum)
        sums[q].add(NeumaierSum{p[0], p[1]});
      else
        extremes[q] = extreme(reductions[q], extremes[q], p[0]);
    }
  std::vector<double> reduced;
  for (std::size_t q = 0; q < reductions.size(); ++q)
    reduced.push_back(reductions[q] == MemberReduction::sum ? sums[q].value() : extremes[q]);
  return reduced;
}

// Each process's block partials, gathered in rank order: whole blocks in global order
// (harness/distribution.hpp), so the reduction is the serial run's.
nlohmann::json case_diagnostics(const Problem& problem, const State& initial, const State& finest, double t_end) {
  const CaseReport* report = problem.capability<CaseReport>();
  if (!report) return nlohmann::json::object();
  const std::vector<MemberReduction> reductions = report->diagnostic_reductions();
  std::vector<double> partials = diagnostic_partials(*report, 0, initial, finest, t_end);
  if (distribution().ranks() > 1) partials = distribution().all_gathered(partials);
  return report->diagnostics(reduced_diagnostics(reductions, partials), t_end);
}

}  // namespace dlpverify
