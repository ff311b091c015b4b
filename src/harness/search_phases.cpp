#include "harness/search_phases.hpp"

#include <chrono>
#include <cmath>
#include <limits>

#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"
#include "io/format.hpp"

namespace dlpverify::search_phase {

double half_width(const OrderFit& fit) {
  return fit.valid && std::isfinite(fit.ci_low) ? 0.5 * (fit.ci_high - fit.ci_low)
                                                : std::numeric_limits<double>::infinity();
}

namespace {

enum class Settled { no, interval, round_off };

// Whether variable v needs no finer level, and how it was settled (into `note`). A finest level at
// the floor settles it as round-off even when its interval is narrow: the floor is what the search
// reached. Orders that step away as a lower-order term makes them (unsettled_orders: by more than a
// fifth of the interval's target half-width) never settle.
Settled settle_variable(const OrderAnalysis& a, const LevelSearchRules& rules, double expected, double ratio,
               std::string& note) {
  const int fitted = static_cast<int>(a.fit.levels.size());
  if (a.exact_to_round_off) {
    note = "exact to round-off at every level";
    return Settled::interval;
  }
  const bool narrow = fitted >= rules.min_fit_levels && half_width(a.fit) <= rules.order_half_width;
  const std::string interval = printf_string("order interval half-width %.3f", half_width(a.fit)) +
                               (narrow ? printf_string(" <= %.3f", rules.order_half_width) : std::string()) +
                               printf_string(" over %d levels", fitted);
  if (!a.status.empty() && a.status.back() == LevelStatus::round_off) {
    note = "finest level at the round-off floor: " + a.rule.back() + (fitted >= 2 ? "; " + interval : "");
    return Settled::round_off;
  }
  if (const std::string moving = unsettled_orders(a, expected > 0.0 ? expected : a.fit.value, ratio, 0.2 * rules.order_half_width); !moving.empty()) {
    note = interval + "; " + moving;
    return Settled::no;
  }
  if (narrow && a.finest_orders.size() < 3) {
    note = interval + "; three pairwise orders show whether they settle";
    return Settled::no;
  }
  if (narrow) {
    note = interval;
    return Settled::interval;
  }
  note = fitted >= 2 ? interval : printf_string("%d level(s) in the asymptotic range", fitted);
  return Settled::no;
}

// Whether every variable's first level sits at the round-off floor: the start is too fine.
bool start_at_round_off(const StudyResult& result) {
  for (const OrderAnalysis& a : result.orders)
    if (a.status.empty() || a.status.front() != LevelStatus::round_off) return false;
  return !result.orders.empty();
}

// The smallest margin of the finest level over the reference's estimated error, and its variable.
std::size_t thinnest_margin(const StudyResult& result) {
  std::size_t thinnest = 0;
  for (std::size_t v = 1; v < result.reference.margin.size(); ++v)
    if (result.reference.margin[v] < result.reference.margin[thinnest]) thinnest = v;
  return thinnest;
}

// Whether some variable that is not exact has fewer than min_fit_levels levels in its fit.
bool window_too_short(const StudyResult& result, const LevelSearchRules& rules) {
  for (const OrderAnalysis& a : result.orders)
    if (!a.exact_to_round_off && static_cast<int>(a.fit.levels.size()) < rules.min_fit_levels) return true;
  return false;
}

// Whether every variable's coarsest level is in the asymptotic range: a coarser one may be too.
bool coarsest_ok(const StudyResult& result) {
  for (const OrderAnalysis& a : result.orders)
    if (a.status.empty() || a.status.front() != LevelStatus::ok) return false;
  return true;
}

// Starts the search again from Δt_0 × r, when t_end / Δt stays whole and coarsenings are left;
// the levels run so far are set aside with `why`.
Decision restart_coarser(Search& s, const std::string& why) {
  if (s.coarsenings >= s.rules.max_coarsenings) return Decision::go_on();
  StudyPlan coarser = s.plan;
  coarser.coarsest_dt *= coarser.ratio;
  coarser.levels = 1;
  try {
    level_steps(coarser);
  } catch (const InputError&) {
    return Decision::go_on();  // no whole coarser step: keep what there is
  }
  for (SearchedLevel& level : s.record.run)
    if (level.kept) {
      level.kept = false;
      level.note = why + ": coarsened by the ratio";
    }
  ++s.coarsenings;
  coarser.levels = 0;
  s.plan = coarser;
  s.left_out.reset();
  s.levels.clear();
  s.previous = s.before_previous = State{};
  return Decision::start_over();
}

}  // namespace

Decision refine(const Search& s, double elapsed, long& steps) {
  const int n = static_cast<int>(s.levels.size());
  if (n >= s.rules.max_levels)
    return Decision::stop_at(SearchStop::level_limit,
                             printf_string("%d levels were kept, the most a search keeps", n));
  // A level costs about its steps: the next one about ratio × the last one's wall time. Under
  // mpirun the ranks' clocks differ, so they agree (any rank past the budget stops them all) and
  // every rank takes the same levels.
  const double next = n > 0 ? s.levels.back().wall_seconds * s.plan.ratio : 0.0;
  if (n >= 2 && distribution().any(elapsed + next > s.rules.budget_seconds))
    return Decision::stop_at(SearchStop::budget,
                             printf_string("the next level would take about %.3g s, past the budget of %.3g s (%.3g s spent)",
                                           next, s.rules.budget_seconds, elapsed));
  StudyPlan next_plan = s.plan;
  next_plan.levels = n + 1;
  try {
    steps = level_steps(next_plan).back();
  } catch (const InputError& e) {
    if (n == 0) throw;
    return Decision::stop_at(SearchStop::step_limit, "no finer level: " + e.reason());
  }
  return Decision::go_on();
}

Decision coarsen_start(Search& s) {
  if (s.levels.size() == 2 && start_at_round_off(s.result))
    return restart_coarser(s, "the start is at the round-off floor");
  return Decision::go_on();
}

Decision coarsen_short_window(Search& s, Decision stop) {
  if (!window_too_short(s.result, s.rules) || !coarsest_ok(s.result)) return stop;
  const Decision coarser =
      restart_coarser(s, stop.stop == SearchStop::reference_accuracy
                             ? "the reference's accuracy was reached before three asymptotic levels"
                             : "the round-off floor was reached before three asymptotic levels");
  return coarser.decided() ? coarser : stop;
}

Decision tighten_reference(Search& s, const TightenReference& tighten) {
  if (s.result.reference.trusted || !tighten || static_cast<int>(s.record.tightenings.size()) >= s.rules.max_tightenings)
    return Decision::go_on();
  const std::size_t v = thinnest_margin(s.result);
  const double margin = s.result.reference.margin[v];
  std::optional<TighterReference> tighter = tighten();
  if (!tighter) return Decision::go_on();
  s.record.tightenings.push_back(printf_string("to %s: level %zu's %s error was only %.3g x the reference's estimated "
                                               "error (needs %.0f x)",
                                               tighter->detail.c_str(), s.levels.size() - 1,
                                               s.plan.variables[v].name.c_str(), margin, kMinimumReferenceMargin));
  for (SearchedLevel& level : s.record.run)
    if (level.kept) {
      level.kept = false;
      level.note = "measured against the reference before it was tightened: solved again";
    }
  s.tighter = std::move(tighter);
  s.left_out.reset();
  s.reference = &s.tighter->state;
  s.reference_error = &s.tighter->error_estimate;
  s.levels.clear();
  s.previous = s.before_previous = State{};
  s.plan.levels = 0;
  return Decision::start_over();
}

Decision reference_accuracy(Search& s) {
  if (s.result.reference.trusted) return Decision::go_on();
  const std::size_t v = thinnest_margin(s.result);
  std::string reason = printf_string("level %zu's %s error is only %.3g x the reference's estimated error (needs %.0f x)",
                                     s.levels.size() - 1, s.plan.variables[v].name.c_str(), s.result.reference.margin[v],
                                     kMinimumReferenceMargin);
  if (s.levels.size() <= 2) return Decision::stop_at(SearchStop::reference_accuracy, reason);
  s.record.run.back().kept = false;
  s.record.run.back().note = "within 100 x of the reference's estimated error: left out";
  s.left_out = std::move(s.levels.back());
  s.left_out_state = std::move(s.previous);
  s.levels.pop_back();
  s.previous = std::move(s.before_previous);
  s.plan.levels = static_cast<int>(s.levels.size());
  s.result = analyse_study(s.plan, s.levels, *s.reference_error, State{});
  return Decision::stop_at(SearchStop::reference_accuracy, reason + "; it is left out");
}

std::vector<std::string> settling_notes(const Search& s) {
  std::vector<std::string> notes;
  for (std::size_t v = 0; v < s.result.orders.size(); ++v) {
    std::string note;
    settle_variable(s.result.orders[v], s.rules, s.plan.expected_order, s.plan.ratio, note);
    notes.push_back(s.plan.variables[v].name + ": " + note);
  }
  return notes;
}

// Every variable's settling; a stop when all are settled, and confirmed at one more level. The
// search never refines on to the round-off floor: levels at or near it are not the ones a verdict
// should rest on.
Decision settle(Search& s) {
  bool all = true, round_off = false;
  for (const OrderAnalysis& a : s.result.orders) {
    std::string note;
    const Settled how = settle_variable(a, s.rules, s.plan.expected_order, s.plan.ratio, note);
    all = all && how != Settled::no;
    round_off = round_off || how == Settled::round_off;
  }
  s.record.settled = settling_notes(s);
  if (!all || static_cast<int>(s.levels.size()) < s.rules.min_fit_levels) {
    s.settled_in_a_row = 0;
    return Decision::go_on();
  }
  ++s.settled_in_a_row;
  if (round_off)
    return Decision::stop_at(SearchStop::round_off, "the round-off floor was reached before the order interval narrowed to " +
                                                        printf_string("±%.3g", s.rules.order_half_width));
  if (s.settled_in_a_row < 2) return Decision::go_on();  // one level more confirms the window: a settling seen once may be passing
  return Decision::stop_at(SearchStop::order_interval,
                           printf_string("every fitted order's 95%% interval is within ±%.3g", s.rules.order_half_width));
}

Decision decided(Search& s, const FailsCheck& fails) {
  if (!fails || static_cast<int>(s.levels.size()) < s.rules.min_fit_levels + 1) {
    s.failed_in_a_row = 0;
    return Decision::go_on();
  }
  s.failed_in_a_row = fails(s.result) ? s.failed_in_a_row + 1 : 0;
  if (s.failed_in_a_row < 2) return Decision::go_on();
  return Decision::stop_at(SearchStop::decided,
                           printf_string("the check failed at levels %zu and %zu alike: finer levels would not change it",
                                         s.levels.size() - 2, s.levels.size() - 1));
}

std::vector<std::optional<OrderExtrapolation>> extrapolate_unsettled(const StudyResult& result,
                                                                     const LevelSearchRules& rules) {
  std::vector<std::optional<OrderExtrapolation>> extrapolations(result.orders.size());
  for (std::size_t v = 0; v < result.orders.size(); ++v) {
    const OrderAnalysis& a = result.orders[v];
    const bool narrow = static_cast<int>(a.fit.levels.size()) >= rules.min_fit_levels &&
                        half_width(a.fit) <= rules.order_half_width;
    if (a.exact_to_round_off || narrow) continue;
    OrderExtrapolation x = extrapolate_order(a);
    if (result.reference.margin[v] < kMinimumReferenceMargin) {
      x.computed = false;
      x.refusal = "the finest level is not trusted against the reference";
    }
    extrapolations[v] = std::move(x);
  }
  return extrapolations;
}

}  // namespace dlpverify::search_phase
