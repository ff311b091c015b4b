/// @file
/// A study that chooses its own levels (`--levels auto`, docs/verification.md, "Levels found by the
/// study"): it starts from the plan's coarsest Δt and refines by the plan's ratio, one level at a
/// time, until every measured variable is settled:
///
/// - its fitted order's 95% interval has a half-width at most `order_half_width` over at least
///   `min_fit_levels` levels in the asymptotic range (LevelStatus::ok), or
/// - its finest level is at the round-off floor (or every level is exact to round-off): a finer
///   level could only add rounding.
///
/// It never refines on to the round-off floor to judge: the levels a verdict rests on are above it.
/// A check's verdict (FailsCheck) of fail at two levels in a row also stops it: finer levels of a
/// method that misses its order only confirm the miss.
///
/// A new level whose error is less than kMinimumReferenceMargin times the reference's estimated
/// error asks for a tighter reference (TightenReference: CVODE's rtol ÷ 100 down to its floor, an
/// integrator's Δt ÷ the ratio, at most `max_tightenings` times); the levels kept so far are solved
/// again against it and the search goes on. When the reference can be made no tighter the search
/// stops there (that level is left out: finer levels would measure the reference). It also stops
/// when `max_levels` are kept, or when the budget is spent. Levels coarser than the
/// asymptotic range (unstable, pre-asymptotic) are set aside by the order analysis' own rules and
/// refinement goes on; a start whose first level is already at the round-off floor for every
/// variable is coarsened by the ratio (at most `max_coarsenings` times, while t_end / Δt stays
/// whole) and the search starts again from there.
///
/// A search that stops on anything but the order interval with some variable's order unsettled
/// (not exact, interval not narrow) tries to extrapolate that variable's order from its pairwise
/// orders (order_extrapolation.hpp); `check` judges such a variable by the extrapolated order when
/// one was made. When it stopped on the reference's accuracy with the reference at its tightest
/// and the extrapolation is refused for want of pairwise orders (fewer than three trusted), the
/// search refines on by the ratio from the level it left out, outside the fit, measuring the
/// differences between successive levels (no reference needed), until their pairwise orders give
/// an extrapolate from four orders, depart from the geometric pattern, come within 10 x of the
/// round-off floor, or a level, step or budget limit stops it; that extrapolate (source
/// "self-differences") replaces the refusal.
///
/// Every rule but the budget counts levels and errors, so a search that ends on them ends at the
/// same levels on any machine; the budget (wall time) only stops a search that would otherwise go
/// on.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/order_extrapolation.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// When a level search stops.
struct LevelSearchRules {
  double order_half_width = 0.05;  ///< target half-width of the fitted order's 95% interval
  int min_fit_levels = 3;          ///< asymptotic levels the interval must be fitted over
  /// Wall time of the levels; no level is started that would exceed it. A minute: each level costs
  /// r times the one before, so ten times the budget buys only log_r 10 (3.3 at r = 2) more levels,
  /// and a study that has not settled in a minute is one for extended precision or coarser levels.
  double budget_seconds = 60.0;
  int max_levels = 30;             ///< levels kept in the study
  int max_coarsenings = 8;         ///< how often a start at the round-off floor is coarsened
  int max_tightenings = 4;         ///< how often the reference is made tighter
};

/// Why a level search stopped.
enum class SearchStop {
  order_interval,      ///< every variable's order interval is narrow enough (or exact to round-off)
  round_off,           ///< a variable reached the round-off floor (short of the interval, or refined on to it)
  reference_accuracy,  ///< a finer level would be within 100× of the reference's own error, which is at its tightest
  budget,              ///< the next level would exceed the wall-time budget
  level_limit,         ///< max_levels were kept
  step_limit,          ///< the next level's steps are not whole or too many (level_steps)
  decided,             ///< the check's verdict was fail at two levels in a row
};
/// "order-interval", "round-off", "reference-accuracy", "budget", "level-limit", "step-limit" or
/// "decided".
std::string to_string(SearchStop stop);

/// One level the search solved, kept in the study or not.
struct SearchedLevel {
  double dt = 0.0;        ///< its step
  long steps = 0;         ///< t_end / dt
  bool kept = true;       ///< a level of the study (else a probe the search set aside)
  std::string note;       ///< why a level was set aside; empty when kept
};

/// What the search ran and why it stopped.
struct LevelSearch {
  LevelSearchRules rules;            ///< as searched
  std::vector<SearchedLevel> run;    ///< every level solved, in order
  SearchStop stop = SearchStop::order_interval;  ///< why it stopped
  std::string reason;                ///< the stop in a sentence, with the numbers that decided it
  std::vector<std::string> settled;  ///< per variable: how it was settled, or why not
  /// Each tightening of the reference, in order: what it was tightened to and why.
  std::vector<std::string> tightenings;
  /// Per variable: the order extrapolated from its pairwise orders (or why not), made only when the
  /// search stopped without settling that variable's order; none otherwise.
  std::vector<std::optional<OrderExtrapolation>> extrapolations;
};

/// Whether a check's verdict on the levels kept so far is fail (check_orders), asked after each
/// level; a search without a check has none.
using FailsCheck = std::function<bool(const StudyResult&)>;

/// Refuses rules no search can follow, before any work: an "order interval half-width" outside
/// (0, 1], a "level search budget" outside (0, 1e7] seconds, fewer than 2 "fitted levels", and a
/// "level limit" below them or above kMostLevels. Throws InputError naming the quantity.
void check_search_rules(const LevelSearchRules& rules);

/// The study of `start` (its t_end, coarsest_dt, ratio, expected_order and variables; levels is
/// ignored) with levels chosen under `rules`; `search` receives what was run and why it stopped.
/// `stop`, asked before each level, ends the search with StudyStopped (a signal); `tighten`, when
/// given, is asked for a tighter reference when a level comes too close to the current one; `fails`,
/// when given, whether the check's verdict is fail after each level.
/// Throws InputError when the first level's steps are not whole.
StudyResult search_levels(const StudyPlan& start, const State& reference, const std::vector<double>& reference_error,
                          const Solve& solve, const LevelSearchRules& rules, LevelSearch& search,
                          const std::function<bool()>& stop = {}, const TightenReference& tighten = {},
                          const FailsCheck& fails = {});

/// The console lines of a search: its target, the levels run (kept or set aside, and why), the
/// stop reason and any extrapolated order (named by the variables of `study`).
std::string format_level_search(const LevelSearch& search, const StudyResult& study);
/// The search as JSON: `target_half_width`, `budget_seconds`, `run` (dt, steps, kept, note),
/// `stop`, `reason`, `settled` (per variable name of `study`), `reference_tightenings` and, when one
/// was tried, `extrapolated_order` (per variable name).
nlohmann::json to_json(const LevelSearch& search, const StudyResult& study);

}  // namespace dlpverify
