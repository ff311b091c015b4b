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

/// What a finding means for a CI: it passes, it could not decide, or it fails.
enum class FindingResult { pass, inconclusive, fail };

/// The one rule of what passes: exact, order_within and constant_within pass, inconclusive could
/// not decide, every other outcome fails.
FindingResult result_of(CheckOutcome outcome);

/// What a finding judges of its variable.
enum class Criterion {
  order,           ///< the fitted (or extrapolated) order, or a sweep's exponent, against P ± tolerance
  error_constant,  ///< the error constant against a baseline's (check --baseline)
};

/// One judgement of one measured variable: which variable, on what, with what outcome, and why.
struct Finding {
  std::size_t variable = 0;  ///< its index among the study's variables
  std::string name;          ///< its name ("position")
  Criterion criterion = Criterion::order;  ///< what was judged
  CheckOutcome outcome = CheckOutcome::no_order;  ///< what decided it
  std::string text;          ///< why, as the report prints it after "name: "
  /// result_of(outcome).
  FindingResult result() const { return result_of(outcome); }
  /// "name: text", the line the report prints.
  std::string line() const { return name + ": " + text; }
};

/// The verdict of check_orders: the findings, one or more per variable, in the order judged.
struct CheckVerdict {
  double expected_order = 0.0;  ///< P, the order the integrator claims
  std::vector<double> expected_orders;  ///< each variable's: P, or its own (StudyPlan::expected_order_by_variable)
  double tolerance = 0.0;       ///< a fitted order p passes when |p − P| ≤ tolerance
  std::vector<Finding> findings;  ///< why each variable passed, failed or could not decide

  /// Every finding passed.
  bool passed() const { return worst() == FindingResult::pass; }
  /// No finding failed, but some could not decide: exit code 5.
  bool inconclusive() const { return worst() == FindingResult::inconclusive; }
  /// The worst result of any finding (fail over inconclusive over pass); pass with none.
  FindingResult worst() const;
  /// The exit code of this verdict: 0 passed, 5 inconclusive, 1 failed.
  int exit_code() const;
  /// Whether any finding has this outcome.
  bool has(CheckOutcome outcome) const;
  /// Each finding's line, in order.
  std::vector<std::string> lines() const;
  /// The finding of variable `variable` on `criterion`, or nullptr.
  const Finding* find(std::size_t variable, Criterion criterion) const;
  /// The worst finding of variable `variable` (the first of equal severity), or nullptr.
  const Finding* worst_of(std::size_t variable) const;
};

/// The relative band of the error-constant gate, |C − C_base| ≤ this × C_base, by default (check
/// --constant-tolerance, compare): reruns on one build are bit for bit, builds and CVODE references
/// move C by less than 1e-8, and the midpoint and Heun methods on drag are 1.5 times apart
/// (docs/verification.md).
inline constexpr double kDefaultConstantTolerance = 0.05;

/// The verdict on `study` for an integrator of order `expected_order`, one order finding per
/// measured variable. A variable passes when it is exact to round-off or its fitted order over the
/// asymptotic window is within its expected order P ± tolerance — expected_order, or its own in the
/// study's plan (expected_order_by_variable) — and its finest pairwise orders settle there
/// (unsettled_orders, and not the two finest outside the band on one side), else it is
/// inconclusive; above the band it is inconclusive (no order below P is seen). Below it, the
/// variable is inconclusive when the window's finest pairwise orders still move towards P and may
/// reach the band (a two-term error C Δt^P (1 + D Δt^q), q ≥ 1, moves them by at most their last
/// change / (r − 1) more), when rounding may move them into it (OrderAnalysis::rounding_spread), or
/// when the round-off floor or the reference's accuracy leaves fewer than three levels; otherwise it
/// fails. It fails too with no order (fewer than two levels and no floor).
///
/// With a level search (`search` not null): a variable whose straight fit did not settle and whose
/// order the search extrapolated from its pairwise orders (LevelSearch::extrapolations) is judged
/// by the extrapolated order instead (pass when |p∞ − P| ≤ tolerance); a search stopped by a limit
/// (its budget, the level or step limit) before a variable's fit had `rules.min_fit_levels` levels
/// fails that variable with no_order, unless its order was extrapolated (docs/verification.md,
/// "What check decides").
CheckVerdict check_orders(const StudyResult& study, double expected_order, double tolerance,
                          const LevelSearch* search = nullptr);

}  // namespace dlpverify
