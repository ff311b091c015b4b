#include "dlpverify/level_search.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <sstream>

#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"
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
  }
  return "?";
}

namespace {

// Half-width of the fitted order's 95% interval; infinite without an interval.
double half_width(const OrderFit& fit) {
  return fit.valid && std::isfinite(fit.ci_low) ? 0.5 * (fit.ci_high - fit.ci_low)
                                                : std::numeric_limits<double>::infinity();
}

enum class Settled { no, interval, round_off };

// Whether variable v needs no finer level, and how it was settled (into `note`). A finest level at
// the floor settles it as round-off even when its interval is narrow: the floor is what the search
// reached. Orders that step away as a lower-order term makes them (unsettled_orders: by more than a
// fifth of the interval's target half-width) never settle.
Settled settle(const OrderAnalysis& a, const LevelSearchRules& rules, double expected, double ratio,
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

// Levels still to refine before variable v's finest level reaches its round-off floor: its error
// falls by r^p a level (p its fitted order) while the floor ½ε√n‖y‖ rises by √r, so
//   n = ⌈ln(e_L / floor_L) / ((p + ½) ln r)⌉.
// None for an exact variable or one without a fitted order.
std::optional<int> levels_to_floor(const StudyResult& result, std::size_t v) {
  const OrderAnalysis& a = result.orders[v];
  if (a.exact_to_round_off || !a.fit.valid || !(a.fit.value > 0.0) || a.floor.empty()) return std::nullopt;
  const double error = result.levels.back().norms[v].l2, floor = a.floor.back();
  if (!(error > floor) || !(floor > 0.0)) return 0;
  return static_cast<int>(std::ceil(std::log(error / floor) / ((a.fit.value + 0.5) * std::log(result.plan.ratio))));
}

// The fewest levels any variable needs to reach its floor (none when no variable predicts one).
std::optional<int> nearest_floor(const StudyResult& result) {
  std::optional<int> nearest;
  for (std::size_t v = 0; v < result.orders.size(); ++v) {
    const std::optional<int> n = levels_to_floor(result, v);
    if (n && (!nearest || *n < *nearest)) nearest = n;
  }
  return nearest;
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

// The search's state: the levels kept so far and the last two states (a level left out for the
// reference's accuracy hands the finest state back to the level before it).
struct Search {
  StudyPlan plan;
  const State* reference = nullptr;            // the reference the levels are measured against …
  const std::vector<double>* reference_error = nullptr;  // … and its estimated error
  std::optional<TighterReference> tighter;     // the tightest reference asked for, if any
  std::vector<LevelResult> levels;
  std::optional<int> interval_met_at;          // the finest level when every interval first was narrow
  int settled_in_a_row = 0;                    // levels in a row at which every variable settled
  State previous, before_previous;
  StudyResult result;
  std::optional<LevelResult> left_out;         // the level left out for the reference's accuracy …
  State left_out_state;                        // … and its state, where refinement by self-differences goes on
};

// Every variable's settling; true when all are settled, with the stop and its reason. Intervals
// met while the round-off floor is predicted within rules.floor_levels levels do not stop the
// search: it goes on to the floor, where the method's convergence ends.
bool all_settled(Search& s, const LevelSearchRules& rules, LevelSearch& search) {
  bool all = true, round_off = false;
  search.settled.clear();
  for (std::size_t v = 0; v < s.result.orders.size(); ++v) {
    std::string note;
    const Settled how = settle(s.result.orders[v], rules, s.plan.expected_order, s.plan.ratio, note);
    all = all && how != Settled::no;
    round_off = round_off || how == Settled::round_off;
    search.settled.push_back(s.plan.variables[v].name + ": " + note);
  }
  if (!all || static_cast<int>(s.levels.size()) < rules.min_fit_levels) {
    s.settled_in_a_row = 0;
    return false;
  }
  ++s.settled_in_a_row;
  if (round_off) {
    search.stop = SearchStop::round_off;
    search.reason = s.interval_met_at
                        ? printf_string("the order interval was within ±%.3g at level %d and refinement went on to "
                                        "the round-off floor",
                                        rules.order_half_width, *s.interval_met_at)
                        : "the round-off floor was reached before the order interval narrowed to " +
                              printf_string("±%.3g", rules.order_half_width);
    return true;
  }
  if (!s.interval_met_at) s.interval_met_at = static_cast<int>(s.levels.size()) - 1;
  if (s.settled_in_a_row < 2) return false;  // one level more confirms the window: a settling seen once may be passing
  const std::optional<int> to_floor = nearest_floor(s.result);
  if (to_floor && *to_floor <= rules.floor_levels) return false;
  search.stop = SearchStop::order_interval;
  search.reason = printf_string("every fitted order's 95%% interval is within ±%.3g", rules.order_half_width);
  if (to_floor)
    search.reason += printf_string("; the round-off floor is about %d levels finer (the search goes on to it "
                                   "when it is at most %d)",
                                   *to_floor, rules.floor_levels);
  return true;
}

// A search stopped on its way to the floor says that its intervals were already narrow.
void note_going_to_floor(const Search& s, LevelSearch& search) {
  if (s.interval_met_at)
    search.reason += printf_string(" (every order interval was narrow at level %d; the search was going on to "
                                   "the round-off floor)",
                                   *s.interval_met_at);
}

// A new finest level too close to the reference's own error is left out, when two levels stay.
bool beyond_reference(Search& s, LevelSearch& search) {
  if (s.result.reference.trusted) return false;
  const std::size_t v = thinnest_margin(s.result);
  search.stop = SearchStop::reference_accuracy;
  search.reason = printf_string("level %zu's %s error is only %.3g x the reference's estimated error (needs %.0f x)",
                                s.levels.size() - 1, s.plan.variables[v].name.c_str(), s.result.reference.margin[v],
                                kMinimumReferenceMargin);
  note_going_to_floor(s, search);
  if (s.levels.size() <= 2) return true;
  search.run.back().kept = false;
  search.run.back().note = "within 100 x of the reference's estimated error: left out";
  search.reason += "; it is left out";
  s.left_out = std::move(s.levels.back());
  s.left_out_state = std::move(s.previous);
  s.levels.pop_back();
  s.previous = std::move(s.before_previous);
  s.plan.levels = static_cast<int>(s.levels.size());
  s.result = analyse_study(s.plan, s.levels, *s.reference_error, State{});
  return true;
}

// A new finest level too close to the reference's own error asks for a tighter reference; the
// levels are then solved again from the coarsest against it (each level's error is measured
// against the reference when it is solved, and the search keeps only the latest states). True
// when the reference was tightened.
bool tighten_reference(Search& s, const TightenReference& tighten, const LevelSearchRules& rules, LevelSearch& search) {
  if (s.result.reference.trusted || !tighten || static_cast<int>(search.tightenings.size()) >= rules.max_tightenings)
    return false;
  const std::size_t v = thinnest_margin(s.result);
  const double margin = s.result.reference.margin[v];
  std::optional<TighterReference> tighter = tighten();
  if (!tighter) return false;
  search.tightenings.push_back(printf_string("to %s: level %zu's %s error was only %.3g x the reference's estimated "
                                             "error (needs %.0f x)",
                                             tighter->detail.c_str(), s.levels.size() - 1,
                                             s.plan.variables[v].name.c_str(), margin, kMinimumReferenceMargin));
  for (SearchedLevel& level : search.run)
    if (level.kept) {
      level.kept = false;
      level.note = "measured against the reference before it was tightened: solved again";
    }
  s.tighter = std::move(tighter);
  s.left_out.reset();
  s.reference = &s.tighter->state;
  s.reference_error = &s.tighter->error_estimate;
  s.levels.clear();
  s.interval_met_at.reset();
  s.previous = s.before_previous = State{};
  s.plan.levels = 0;
  return true;
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
// the levels run so far are set aside with `why`. True when it did.
bool restart_coarser(Search& s, const LevelSearchRules& rules, int& coarsenings, LevelSearch& search,
                     const std::string& why) {
  if (coarsenings >= rules.max_coarsenings) return false;
  StudyPlan coarser = s.plan;
  coarser.coarsest_dt *= coarser.ratio;
  coarser.levels = 1;
  try {
    level_steps(coarser);
  } catch (const InputError&) {
    return false;  // no whole coarser step: keep what there is
  }
  for (SearchedLevel& level : search.run)
    if (level.kept) {
      level.kept = false;
      level.note = why + ": coarsened by the ratio";
    }
  ++coarsenings;
  coarser.levels = 0;
  s.plan = coarser;
  s.left_out.reset();
  s.levels.clear();
  s.interval_met_at.reset();
  s.previous = s.before_previous = State{};
  return true;
}

// A start too fine: its first level at the round-off floor for every variable (on two levels), or
// the floor or the reference's accuracy reached before the asymptotic window holds min_fit_levels
// levels while the coarsest level is still asymptotic.
bool coarsen(Search& s, const LevelSearchRules& rules, int& coarsenings, LevelSearch& search, bool limit_reached) {
  if (s.levels.size() == 2 && start_at_round_off(s.result))
    return restart_coarser(s, rules, coarsenings, search, "the start is at the round-off floor");
  if (limit_reached && window_too_short(s.result, rules) && coarsest_ok(s.result))
    return restart_coarser(s, rules, coarsenings, search,
                           search.stop == SearchStop::reference_accuracy
                               ? "the reference's accuracy was reached before three asymptotic levels"
                               : "the round-off floor was reached before three asymptotic levels");
  return false;
}

// Why no further level may start (budget, level limit, whole steps), or false.
bool cannot_refine(Search& s, const LevelSearchRules& rules, double elapsed, LevelSearch& search, long& steps) {
  const int n = static_cast<int>(s.levels.size());
  if (n >= rules.max_levels) {
    search.stop = SearchStop::level_limit;
    search.reason = printf_string("%d levels were kept, the most a search keeps", n);
    note_going_to_floor(s, search);
    return true;
  }
  // A level costs about its steps: the next one about ratio × the last one's wall time. Under
  // mpirun the ranks' clocks differ, so they agree (any rank past the budget stops them all) and
  // every rank takes the same levels.
  const double next = n > 0 ? s.levels.back().wall_seconds * s.plan.ratio : 0.0;
  if (n >= 2 && distribution().any(elapsed + next > rules.budget_seconds)) {
    search.stop = SearchStop::budget;
    search.reason = printf_string("the next level would take about %.3g s, past the budget of %.3g s (%.3g s spent)",
                                  next, rules.budget_seconds, elapsed);
    note_going_to_floor(s, search);
    return true;
  }
  StudyPlan next_plan = s.plan;
  next_plan.levels = n + 1;
  try {
    steps = level_steps(next_plan).back();
  } catch (const InputError& e) {
    if (n == 0) throw;
    search.stop = SearchStop::step_limit;
    search.reason = "no finer level: " + e.reason();
    note_going_to_floor(s, search);
    return true;
  }
  return false;
}

// The order of each variable the search could not settle (not exact, interval not narrow),
// extrapolated from its pairwise orders over the kept levels, which the reference trusts.
void extrapolate_unsettled(const StudyResult& result, const LevelSearchRules& rules, LevelSearch& search) {
  search.extrapolations.assign(result.orders.size(), std::nullopt);
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
    search.extrapolations[v] = std::move(x);
  }
}

// A self-difference within this factor of its level's round-off floor (½ ε √n ‖y‖,
// round_off_floor) is rounding as much as convergence: it and finer ones are not used. Above it,
// rounding that bends the pairwise orders breaks their geometric pattern and the extrapolation
// refuses. (RK4 on cooling, 20 particles: 2.0e-10 K at 0.3125 ms, 20 x its floor, orders still
// converging geometrically, measured.)
constexpr double kSelfDifferenceFloorFactor = 10.0;
// Pairwise orders of the self-differences wanted: four give two Aitken extrapolates, whose
// spread enters the uncertainty.
constexpr std::size_t kSelfDifferenceOrders = 4;

// The variables whose extrapolation from the reference errors was refused for want of pairwise
// orders (fewer than three trusted).
std::vector<std::size_t> short_of_orders(const LevelSearch& search) {
  std::vector<std::size_t> wanted;
  for (std::size_t v = 0; v < search.extrapolations.size(); ++v) {
    const std::optional<OrderExtrapolation>& x = search.extrapolations[v];
    if (x && !x->computed && x->pairwise.size() < 3) wanted.push_back(v);
  }
  return wanted;
}

// Variable v's differences between successive levels, trusted then beyond, with the finer Δt of
// each; false when the newest one is within kSelfDifferenceFloorFactor of its round-off floor
// (it is left out).
bool self_differences(const StudyResult& result, const std::vector<LevelResult>& beyond, std::size_t v,
                      std::vector<double>& difference, std::vector<double>& dt) {
  difference.clear();
  dt.clear();
  auto add = [&](const LevelResult& level) {
    if (!level.self_difference[v]) return true;
    const LevelErrors at{level.dt, level.steps, *level.self_difference[v], level.norms[v].reference_l2};
    if (!(at.error > kSelfDifferenceFloorFactor * round_off_floor(at))) return false;
    difference.push_back(at.error);
    dt.push_back(level.dt);
    return true;
  };
  for (const LevelResult& level : result.levels) add(level);
  for (const LevelResult& level : beyond)
    if (!add(level)) return false;
  return true;
}

// Why no level beyond the reference's trust may start (budget, level limit, whole steps), or empty.
std::string cannot_go_beyond(const StudyPlan& plan, const std::vector<LevelResult>& beyond, int levels,
                             const LevelSearchRules& rules, double elapsed, long& steps) {
  if (levels >= rules.max_levels) return printf_string("%d levels were solved, the most a search keeps", levels);
  const double next = beyond.back().wall_seconds * plan.ratio;
  if (distribution().any(elapsed + next > rules.budget_seconds))  // agreed between ranks, as in cannot_refine
    return printf_string("the next level would take about %.3g s, past the budget of %.3g s", next,
                         rules.budget_seconds);
  StudyPlan next_plan = plan;
  next_plan.levels = levels + 1;
  try {
    steps = level_steps(next_plan).back();
  } catch (const InputError& e) {
    return "no finer level: " + e.reason();
  }
  return {};
}

// After a stop on the reference's accuracy, the reference at its tightest, with some variable's
// extrapolation refused for want of pairwise orders: refines on from the level left out, by the ratio, measuring the differences
// between successive levels (no reference needed; each level's error against the reference is
// for information only, outside the fit), until each such variable's self-difference orders
// give an extrapolate from four pairwise orders, depart from the geometric pattern, reach the
// round-off floor, or a limit stops it. The extrapolate replaces the refusal.
void refine_by_self_differences(Search& s, const StudyResult& result, const Solve& solve, const LevelSearchRules& rules,
                                double spent, const std::function<bool()>& stop, LevelSearch& search) {
  const std::vector<std::size_t> wanted = short_of_orders(search);
  if (wanted.empty() || !s.left_out) return;
  const std::string note = "beyond the reference's trust: its difference from the level before is used for the "
                           "self-difference orders, its error against the reference only for information";
  search.run.back().note = note;
  std::vector<LevelResult> beyond{*s.left_out};
  State previous = std::move(s.left_out_state);
  const auto begin = std::chrono::steady_clock::now();
  std::string ended;
  for (;;) {
    bool done = true;
    for (std::size_t v : wanted) {
      std::vector<double> difference, dt;
      const bool above_floor = self_differences(result, beyond, v, difference, dt);
      OrderExtrapolation x = extrapolate_self_differences(difference, s.plan.ratio);
      x.difference_dt.assign(dt.end() - static_cast<std::ptrdiff_t>(std::min(dt.size(), x.pairwise.size() + 1)),
                             dt.end());
      x.reference_trusted_to = result.levels.back().dt;
      if (!above_floor) ended = s.plan.variables[v].name + "'s newest self-difference is within 10 x of its round-off floor";
      else if (!x.computed && x.pairwise.size() >= 3)
        ended = s.plan.variables[v].name + "'s self-difference orders depart from the geometric pattern";
      done = done && x.computed && x.pairwise.size() >= kSelfDifferenceOrders;
      search.extrapolations[v] = std::move(x);
    }
    if (done) ended = "the self-difference orders were extrapolated";
    const double elapsed = spent + std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    long steps = 0;
    const int levels = static_cast<int>(result.levels.size() + beyond.size());
    if (ended.empty()) ended = cannot_go_beyond(s.plan, beyond, levels, rules, elapsed, steps);
    if (!ended.empty()) break;
    if (stop && stop()) throw StudyStopped(levels);
    StudyPlan plan = s.plan;
    plan.levels = levels + 1;
    State state;
    beyond.push_back(run_level(plan, levels, steps, *s.reference, solve, &previous, state));
    search.run.push_back({beyond.back().dt, steps, false, note});
    previous = std::move(state);
  }
  search.reason += printf_string("; refinement went on %zu level(s) beyond the reference's trust for the differences "
                                 "between successive levels (",
                                 beyond.size()) +
                   ended + ")";
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
                          const std::function<bool()>& stop, const TightenReference& tighten) {
  StudyPlan first = start;  // the search decides the levels: its start is one
  first.levels = 1;
  check_plan(first, 1);
  search = LevelSearch{};
  search.rules = rules;
  Search s;
  s.reference = &reference;
  s.reference_error = &reference_error;
  s.plan = start;
  s.plan.levels = 0;
  int coarsenings = 0;
  const auto begin = std::chrono::steady_clock::now();
  for (;;) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    long steps = 0;
    if (cannot_refine(s, rules, elapsed, search, steps)) break;
    const int k = static_cast<int>(s.levels.size());
    if (stop && stop()) throw StudyStopped(k);
    s.plan.levels = k + 1;
    State state;
    s.levels.push_back(run_level(s.plan, k, steps, *s.reference, solve, k > 0 ? &s.previous : nullptr, state));
    search.run.push_back({s.levels.back().dt, steps, true, ""});
    s.before_previous = std::move(s.previous);
    s.previous = std::move(state);
    s.result = analyse_study(s.plan, s.levels, *s.reference_error, State{});
    if (coarsen(s, rules, coarsenings, search, false)) continue;
    if (tighten_reference(s, tighten, rules, search)) continue;
    const bool limit = beyond_reference(s, search) || all_settled(s, rules, search);
    if (limit && coarsen(s, rules, coarsenings, search, true)) continue;
    if (limit) break;
  }
  if (s.levels.empty()) throw InputError("level search", "auto", "no level could be run: " + search.reason);
  if (search.stop == SearchStop::reference_accuracy && tighten)
    search.reason += static_cast<int>(search.tightenings.size()) >= rules.max_tightenings
                         ? printf_string("; the reference was tightened %d times, the most a search does",
                                         rules.max_tightenings)
                         : "; the reference can be made no tighter";
  StudyResult result = analyse_study(s.plan, std::move(s.levels), *s.reference_error, std::move(s.previous));
  // The settling notes of the levels as kept (after a level left out for the reference).
  LevelSearch kept = search;
  all_settled(s, rules, kept);
  search.settled = kept.settled;
  if (search.stop != SearchStop::order_interval) extrapolate_unsettled(result, rules, search);
  // Only a reference at its tightest hands over to the self-differences: one the search stopped
  // tightening (max_tightenings) could still be made tighter, and is the better judge.
  if (search.stop == SearchStop::reference_accuracy &&
      static_cast<int>(search.tightenings.size()) < rules.max_tightenings)
    refine_by_self_differences(s, result, solve, rules,
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), stop,
                               search);
  return result;
}

std::string format_level_search(const LevelSearch& search, const StudyResult& study) {
  std::ostringstream out;
  out << printf_string("levels found by search (target: order interval ±%.3g over %d asymptotic levels; budget %.3g s)\n",
                       search.rules.order_half_width, search.rules.min_fit_levels, search.rules.budget_seconds);
  for (const SearchedLevel& level : search.run)
    out << printf_string("  dt %10.3e %9ld steps  ", level.dt, level.steps)
        << (level.kept ? "kept" : "set aside: " + level.note) << "\n";
  for (const std::string& line : search.tightenings) out << "  reference tightened " << line << "\n";
  for (const std::string& line : search.settled) out << "  " << line << "\n";
  out << "  stopped (" << to_string(search.stop) << "): " << search.reason << "\n";
  for (std::size_t v = 0; v < search.extrapolations.size() && v < study.plan.variables.size(); ++v)
    if (search.extrapolations[v])
      out << "  " << study.plan.variables[v].name << ": " << describe(*search.extrapolations[v]) << "\n";
  return out.str();
}

nlohmann::json to_json(const LevelSearch& search, const StudyResult& study) {
  nlohmann::json run = nlohmann::json::array();
  for (const SearchedLevel& level : search.run)
    run.push_back({{"dt", level.dt}, {"steps", level.steps}, {"kept", level.kept}, {"note", level.note}});
  nlohmann::json used = nlohmann::json::object(), settled = nlohmann::json::object(),
                 extrapolated = nlohmann::json::object();
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    used[study.plan.variables[v].name] = study.orders[v].fit.levels;
    if (v < search.settled.size()) settled[study.plan.variables[v].name] = search.settled[v];
    if (v < search.extrapolations.size() && search.extrapolations[v])
      extrapolated[study.plan.variables[v].name] = to_json(*search.extrapolations[v]);
  }
  return {{"target_half_width", search.rules.order_half_width},
          {"min_fit_levels", search.rules.min_fit_levels},
          {"budget_seconds", search.rules.budget_seconds},
          {"run", run},
          {"levels_used", used},
          {"stop", to_string(search.stop)},
          {"reason", search.reason},
          {"settled", settled},
          {"reference_tightenings", search.tightenings},
          {"extrapolated_order", extrapolated}};
}

}  // namespace dlpverify
