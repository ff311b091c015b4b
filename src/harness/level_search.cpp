#include "dlpverify/level_search.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <sstream>

#include "dlpverify/errors.hpp"
#include "harness/search_phases.hpp"
#include "io/format.hpp"

namespace dlpverify {

std::string to_string(SearchStop stop) {
  switch (stop) {
    case SearchStop::order_interval: return "order-interval";
    case SearchStop::round_off: return "round-off";
    case SearchStop::reference_accuracy: return "reference-accuracy";
    case SearchStop::budget: return "budget";
    case SearchStop::level_limit: return "level-limit";
    case SearchStop::step_limit: return "step-limit";
    case SearchStop::decided: return "decided";
  }
  return "?";
}

namespace {

using search_phase::Decision;
using search_phase::Search;

// The first phase that decides, in order, after a new level: a start too fine is coarsened, a
// reference too close is tightened, the reference's accuracy, a settled window or a decided check
// stops the search (and a stop that left a window short of levels coarsens it).
Decision after_level(Search& s, const TightenReference& tighten, const FailsCheck& fails) {
  if (Decision d = search_phase::coarsen_start(s); d.decided()) return d;
  if (Decision d = search_phase::tighten_reference(s, tighten); d.decided()) return d;
  Decision d = search_phase::reference_accuracy(s);
  if (!d.decided()) d = search_phase::settle(s);
  if (!d.decided()) d = search_phase::decided(s, fails);
  return d.decided() ? search_phase::coarsen_short_window(s, std::move(d)) : d;
}

}  // namespace

void check_search_rules(const LevelSearchRules& rules) {
  if (!std::isfinite(rules.order_half_width) || rules.order_half_width <= 0.0 || rules.order_half_width > 1.0)
    throw InputError("order interval half-width", value_text(rules.order_half_width), "must lie in (0, 1]");
  if (!std::isfinite(rules.budget_seconds) || rules.budget_seconds <= 0.0 || rules.budget_seconds > 1e7)
    throw InputError("level search budget", value_text(rules.budget_seconds), "must lie in (0, 1e7] seconds");
  if (rules.min_fit_levels < 2)
    throw InputError("fitted levels", std::to_string(rules.min_fit_levels), "must be at least 2");
  if (rules.max_levels < rules.min_fit_levels || rules.max_levels > kMostLevels)
    throw InputError("level limit", std::to_string(rules.max_levels),
                     "must lie in [" + std::to_string(rules.min_fit_levels) + ", " + std::to_string(kMostLevels) + "]");
}

StudyResult search_levels(const StudyPlan& start, const State& reference, const std::vector<double>& reference_error,
                          const Solve& solve, const LevelSearchRules& rules, LevelSearch& search,
                          const std::function<bool()>& stop, const TightenReference& tighten, const FailsCheck& fails) {
  StudyPlan first = start;  // the search decides the levels: its start is one
  first.levels = 1;
  check_plan(first, 1);
  search = LevelSearch{};
  search.rules = rules;
  Search s(rules, search, start);
  s.reference = &reference;
  s.reference_error = &reference_error;
  s.plan.levels = 0;
  const auto begin = std::chrono::steady_clock::now();
  const auto elapsed = [&begin] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(); };
  Decision ended;
  for (;;) {
    long steps = 0;
    ended = search_phase::refine(s, elapsed(), steps);
    if (ended.decided()) break;
    const int k = static_cast<int>(s.levels.size());
    if (stop && stop()) throw StudyStopped(k);
    s.plan.levels = k + 1;
    State state;
    s.levels.push_back(run_level(s.plan, k, steps, *s.reference, solve, k > 0 ? &s.previous : nullptr, state));
    search.run.push_back({s.levels.back().dt, steps, true, ""});
    s.before_previous = std::move(s.previous);
    s.previous = std::move(state);
    s.result = analyse_study(s.plan, s.levels, *s.reference_error, State{});
    ended = after_level(s, tighten, fails);
    if (ended.kind == Decision::Kind::stop) break;
  }
  // The one place the search's stop and reason are written.
  search.stop = ended.stop;
  search.reason = ended.reason;
  if (s.levels.empty()) throw InputError("level search", "auto", "no level could be run: " + search.reason);
  if (search.stop == SearchStop::reference_accuracy && tighten)
    search.reason += static_cast<int>(search.tightenings.size()) >= rules.max_tightenings
                         ? printf_string("; the reference was tightened %d times, the most a search does",
                                         rules.max_tightenings)
                         : "; the reference can be made no tighter";
  StudyResult result = analyse_study(s.plan, std::move(s.levels), *s.reference_error, std::move(s.previous));
  search.settled = search_phase::settling_notes(s);  // of the levels as kept (after a level left out)
  if (search.stop != SearchStop::order_interval && search.stop != SearchStop::decided)
    search.extrapolations = search_phase::extrapolate_unsettled(result, rules);
  // Only a reference at its tightest hands over to the self-differences: one the search stopped
  // tightening (max_tightenings) could still be made tighter, and is the better judge.
  if (search.stop == SearchStop::reference_accuracy &&
      static_cast<int>(search.tightenings.size()) < rules.max_tightenings)
    search.reason += search_phase::refine_by_self_differences(s, result, solve, elapsed(), stop, search.extrapolations);
  return result;
}

}  // namespace dlpverify
