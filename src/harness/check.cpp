#include "dlpverify/check.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/format.hpp"

namespace dlpverify {

namespace {

// The fitted order to 3 decimals, or to as many more as it takes for the printed number to lie on
// the same side of expected ± tolerance as the order itself: 4.100179 outside 4 ± 0.1 prints
// 4.1002, not 4.100.
std::string order_text(double order, double expected, double tolerance) {
  const bool within = std::abs(order - expected) <= tolerance;
  for (int digits = 3; digits <= 17; ++digits) {
    const std::string text = printf_string("%.*f", digits, order);
    if ((std::abs(std::strtod(text.c_str(), nullptr) - expected) <= tolerance) == within) return text;
  }
  return printf_string("%.17g", order);
}

}  // namespace

CheckVerdict check_orders(const StudyResult& study, double expected_order, double tolerance) {
  CheckVerdict verdict;
  verdict.expected_order = expected_order;
  verdict.tolerance = tolerance;
  char line[512];
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const std::string& name = study.plan.variables[v].name;
    const OrderAnalysis& a = study.orders[v];
    const auto own = study.plan.expected_order_by_variable.find(name);
    const double expected = own != study.plan.expected_order_by_variable.end() ? own->second : expected_order;
    verdict.expected_orders.push_back(expected);
    if (a.exact_to_round_off) {
      std::snprintf(line, sizeof line, "%s: pass, every level is exact to round-off", name.c_str());
      verdict.outcomes.push_back(CheckOutcome::exact);
    } else if (!a.fit.valid) {
      verdict.passed = false;
      std::snprintf(line, sizeof line,
                    "%s: FAIL, only %zu level(s) in the asymptotic range: no order measured (over all levels the "
                    "error falls at order %.2f)",
                    name.c_str(), a.fit.levels.size(), a.overall_slope);
      verdict.outcomes.push_back(CheckOutcome::no_order);
    } else {
      const bool within = std::abs(a.fit.value - expected) <= tolerance;
      verdict.passed = verdict.passed && within;
      std::snprintf(line, sizeof line, "%s: %s, fitted order %s %s %.3f +/- %.3f (over %zu levels)", name.c_str(),
                    within ? "pass" : "FAIL", order_text(a.fit.value, expected, tolerance).c_str(),
                    within ? "within" : "outside", expected, tolerance, a.fit.levels.size());
      verdict.outcomes.push_back(within ? CheckOutcome::order_within : CheckOutcome::order_miss);
    }
    verdict.findings.emplace_back(line);
  }
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    if (study.reference.margin[v] >= kMinimumReferenceMargin) continue;
    verdict.passed = false;
    std::snprintf(line, sizeof line,
                  "%s: FAIL, untrustworthy reference: the finest level's error is only %.3g x the reference's "
                  "estimated error %.3e (needs %.0f x); tighten the reference or coarsen the levels",
                  study.plan.variables[v].name.c_str(), study.reference.margin[v], study.reference.error[v],
                  kMinimumReferenceMargin);
    verdict.findings.emplace_back(line);
    verdict.outcomes.push_back(CheckOutcome::untrusted_reference);
  }
  return verdict;
}

void judge_search_coverage(const StudyResult& study, const LevelSearch& search, CheckVerdict& verdict) {
  if (search.stop != SearchStop::budget && search.stop != SearchStop::level_limit && search.stop != SearchStop::step_limit)
    return;
  const auto needed = static_cast<std::size_t>(search.rules.min_fit_levels);
  for (std::size_t v = 0; v < study.orders.size() && v < verdict.outcomes.size(); ++v) {
    const bool extrapolated = v < search.extrapolations.size() && search.extrapolations[v] && search.extrapolations[v]->computed;
    if (extrapolated || verdict.outcomes[v] == CheckOutcome::exact || study.orders[v].fit.levels.size() >= needed) continue;
    verdict.outcomes[v] = CheckOutcome::no_order;
    verdict.findings[v] = printf_string("%s: FAIL, no order measured: the search stopped (%s) with %zu level(s) in the fit, "
                                        "fewer than the %zu an order's interval needs; %s",
                                        study.plan.variables[v].name.c_str(), to_string(search.stop).c_str(),
                                        study.orders[v].fit.levels.size(), needed, search.reason.c_str());
    verdict.passed = false;
  }
}

void judge_by_extrapolated_orders(const StudyResult& study,
                                  const std::vector<std::optional<OrderExtrapolation>>& extrapolations,
                                  CheckVerdict& verdict) {
  const double tolerance = verdict.tolerance;
  for (std::size_t v = 0; v < extrapolations.size() && v < study.orders.size(); ++v) {
    if (!extrapolations[v] || !extrapolations[v]->computed) continue;
    const double expected = v < verdict.expected_orders.size() ? verdict.expected_orders[v] : verdict.expected_order;
    const OrderExtrapolation& x = *extrapolations[v];
    const bool within = std::abs(x.value - expected) <= tolerance;
    verdict.outcomes[v] = within ? CheckOutcome::order_within : CheckOutcome::order_miss;
    verdict.findings[v] = study.plan.variables[v].name + ": " + (within ? "pass, " : "FAIL, ") + describe(x) +
                          printf_string(" %s %.3f +/- %.3f (the fitted order %.3f did not settle)",
                                        within ? "within" : "outside", expected, tolerance, study.orders[v].fit.value);
  }
  verdict.passed = true;
  for (CheckOutcome o : verdict.outcomes)
    verdict.passed = verdict.passed && (o == CheckOutcome::exact || o == CheckOutcome::order_within ||
                                        o == CheckOutcome::constant_within);
}

}  // namespace dlpverify
