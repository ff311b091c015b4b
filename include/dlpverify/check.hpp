/// @file
/// The `check` verdict: is every measured variable's fitted order within P ± tolerance?
///
/// A variable whose every level sits at the round-off floor is exact for the method (the
/// similarity and gravity cases under RK2) and passes. A variable with fewer than two levels in
/// the asymptotic range has no measured order and fails: nothing was proven.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dlpverify/level_search.hpp"
#include "dlpverify/order_extrapolation.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// What decided a finding.
enum class CheckOutcome {
  exact,                ///< every level exact to round-off: pass
  order_within,         ///< fitted order within P ± tolerance: pass
  order_miss,           ///< fitted order outside it, and its pairwise orders cannot reach it: fail
  inconclusive,         ///< outside it, but still moving towards it, within rounding of it, or too few levels above the floor or the reference's accuracy
  no_order,             ///< fewer than two asymptotic levels: fail
  constant_within,      ///< the error constant within the baseline's band (check --baseline): pass
  constant_outside,     ///< the error constant outside it, or on one side only: fail
};

/// The verdict of check_orders: passed when no finding failed, with one finding per variable.
struct CheckVerdict {
  bool passed = true;           ///< every finding passed
  double expected_order = 0.0;  ///< P, the order the integrator claims
  std::vector<double> expected_orders;  ///< each variable's: P, or its own (StudyPlan::expected_order_by_variable)
  double tolerance = 0.0;       ///< a fitted order p passes when |p − P| ≤ tolerance
  std::vector<std::string> findings;   ///< one line per variable, why it passed or failed
  std::vector<CheckOutcome> outcomes;  ///< what decided each finding, in the same order

  /// No finding failed, but some could not decide (CheckOutcome::inconclusive): exit code 5.
  bool inconclusive() const {
    for (CheckOutcome o : outcomes)
      if (o != CheckOutcome::exact && o != CheckOutcome::order_within && o != CheckOutcome::constant_within &&
          o != CheckOutcome::inconclusive)
        return false;
    return !passed;
  }
  /// The exit code of this verdict: 0 passed, 5 inconclusive, 1 failed.
  int exit_code() const;

  /// Whether any finding has this outcome.
  bool has(CheckOutcome outcome) const {
    for (CheckOutcome o : outcomes)
      if (o == outcome) return true;
    return false;
  }
};

/// The relative band of the error-constant gate, |C − C_base| ≤ this × C_base, by default (check
/// --constant-tolerance, compare): reruns on one build are bit for bit, builds and CVODE references
/// move C by less than 1e-8, and the midpoint and Heun methods on drag are 1.5 times apart
/// (docs/verification.md).
inline constexpr double kDefaultConstantTolerance = 0.05;

/// The verdict on `study` for an integrator of order `expected_order`: each measured variable
/// passes when it is exact to round-off or its fitted order over the asymptotic window is within
/// its expected order P ± tolerance — expected_order, or its own in the study's plan
/// (expected_order_by_variable) — and its finest pairwise orders settle there (unsettled_orders,
/// and not the two finest outside the band on one side), else it is inconclusive; above the band
/// it is inconclusive (no order below P is seen). Below it, the variable is inconclusive when the window's finest
/// pairwise orders still move towards P and may reach the band (a two-term error C Δt^P (1 + D Δt^q),
/// q ≥ 1, moves them by at most their last change / (r − 1) more), when rounding may move them into
/// it (OrderAnalysis::rounding_spread), or when the round-off floor leaves fewer than three levels;
/// otherwise it fails. It fails too with no order (fewer than two levels and no floor) and with an
/// untrusted reference (docs/verification.md, "The verdict").
CheckVerdict check_orders(const StudyResult& study, double expected_order, double tolerance);

/// A level search's variables whose straight fit did not settle and whose order was extrapolated
/// from their pairwise orders (`extrapolations`, one per variable, level_search.hpp) are judged by
/// the extrapolated order instead: pass when |p∞ − P| ≤ tolerance, the rule of the fitted order.
/// A refused extrapolation leaves the finding as it was; `verdict.passed` is made again.
void judge_by_extrapolated_orders(const StudyResult& study,
                                  const std::vector<std::optional<OrderExtrapolation>>& extrapolations,
                                  CheckVerdict& verdict);

/// A level search stopped by a limit (its budget, the level or step limit) before any variable's
/// fit had `rules.min_fit_levels` levels has measured no order it can stand behind: a variable
/// whose fit has fewer levels, and whose order was not extrapolated, fails with no_order, its
/// finding naming the stop and what would help. A search that settled, reached the round-off
/// floor or the reference's accuracy is left as judged.
void judge_search_coverage(const StudyResult& study, const LevelSearch& search, CheckVerdict& verdict);

}  // namespace dlpverify
