#include "dlpverify/check.hpp"

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

#include "dlpverify/errors.hpp"
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
  return shortest_text(order);
}

// Levels `from` to `to` as "2-4" (or "2" alone).
std::string level_range(int from, int to) {
  return from == to ? std::to_string(from) : std::to_string(from) + "-" + std::to_string(to);
}

// Where the asymptotic window of `a` begins and ends, and why: "levels 2-4, after pre-asymptotic
// levels 0-1, before the round-off floor at level 5".
std::string window_ends(const OrderAnalysis& a) {
  const std::vector<int>& w = a.fit.levels;
  const int last = static_cast<int>(a.status.size()) - 1;
  std::string text = w.empty() ? std::string("no level") : "levels " + level_range(w.front(), w.back());
  if (!w.empty() && w.front() > 0) text += ", after " + to_string(a.status[0]) + " level" + (w.front() > 1 ? "s " : " ") +
                                           level_range(0, w.front() - 1);
  const int past = w.empty() ? 0 : w.back() + 1;
  if (past <= last && a.status[static_cast<std::size_t>(past)] == LevelStatus::round_off)
    text += ", before the round-off floor at level " + std::to_string(past);
  else if (past <= last && a.status[static_cast<std::size_t>(past)] == LevelStatus::reference)
    text += ", before the reference's accuracy at level " + std::to_string(past);
  else if (past > last)
    text += ", the finest level last";
  return text;
}

// What ends the window from below, the first floor a finer level is at: the round-off floor
// (double precision), the reference's accuracy, or none.
std::optional<LevelStatus> floor_past_window(const OrderAnalysis& a) {
  const std::size_t past = a.fit.levels.empty() ? 0 : static_cast<std::size_t>(a.fit.levels.back()) + 1;
  for (std::size_t k = past; k < a.status.size(); ++k)
    if (a.status[k] == LevelStatus::round_off || a.status[k] == LevelStatus::reference) return a.status[k];
  return std::nullopt;
}

// What would settle an order the window leaves open, after what ends it.
std::string what_would_settle(const OrderAnalysis& a) {
  const std::optional<LevelStatus> floor = floor_past_window(a);
  if (!floor) return "finer levels (a smaller dt, or --levels auto) would settle it";
  if (*floor == LevelStatus::reference)
    return "the reference cannot settle it at these levels: a tighter reference (a smaller reference rtol) or coarser "
           "levels may";
  return "double precision cannot settle it before the floor";
}

// What the judgement of one window reads: the analysis, P, the tolerance, r, and the texts every
// finding shares (the fitted order to the digits that show its side, the band, "over n levels").
struct Window {
  const OrderAnalysis& a;
  double expected, tolerance, ratio;
  std::string order, band, over;
  bool ends_named = false;  // `over` names the window's ends already
  bool band_has(double low, double high) const { return low <= expected + tolerance && high >= expected - tolerance; }
};

using Judgement = std::pair<CheckOutcome, std::string>;

// Inside the band: pass, unless the two finest pairwise orders lie outside it on one side (beyond
// rounding's reach), or the finest orders move away from P as a lower-order term makes them, by
// more than a tenth of the band (unsettled_orders).
Judgement judge_within(const Window& w) {
  std::string away = unsettled_orders(w.a, w.expected, w.ratio, 0.1 * w.tolerance);
  const std::vector<double>& p = w.a.finest_orders;
  const auto outside = [&w](double order) { return order - w.expected > w.tolerance + w.a.rounding_spread ? 1
                                                   : w.expected - order > w.tolerance + w.a.rounding_spread ? -1 : 0; };
  if (p.size() >= 2 && outside(p.back()) != 0 && outside(p.back()) == outside(p[p.size() - 2]))
    away = printf_string("its two finest pairwise orders %.3f and %.3f lie outside it, on one side", p[p.size() - 2], p.back());
  if (away.empty()) return {CheckOutcome::order_within, "pass, fitted order " + w.order + " within " + w.band + " (" + w.over + ")"};
  return {CheckOutcome::inconclusive, "INCONCLUSIVE, fitted order " + w.order + " within " + w.band + ", but " + away + " (" +
                                          w.over + "); finer levels would show whether a lower-order term is emerging"};
}

// Why an order below the band may still be P: the finest pairwise order inside it, orders moving
// towards it that may reach it (at most their last change / (r − 1) more), or rounding. Empty: none.
std::string room_for_p(const Window& w) {
  const OrderAnalysis& a = w.a;
  std::vector<std::string> why;
  double low = a.fit.value, high = a.fit.value;
  if (!a.finest_orders.empty()) {
    const double last = a.finest_orders.back();
    low = std::min(low, last);
    high = std::max(high, last);
    if (w.band_has(last, last)) why.push_back(printf_string("its finest pairwise order %.3f is within it", last));
  }
  if (a.finest_orders.size() >= 2) {
    const double last = a.finest_orders.back(), before = a.finest_orders[a.finest_orders.size() - 2];
    const double reach = last + (last - before) / (w.ratio - 1.0);
    if (last != before && (last > before) == (w.expected > last) && w.band_has(std::min(last, reach), std::max(last, reach)))
      why.push_back(printf_string("its pairwise orders still move towards %.3f (%.3f -> %.3f, at most %.3f next)",
                                  w.expected, before, last, reach));
    low = std::min(low, reach);
    high = std::max(high, reach);
  }
  if (why.empty() && w.band_has(low - a.rounding_spread, high + a.rounding_spread))
    why.push_back(printf_string("rounding may move its finest pairwise order by %.3f", a.rounding_spread));
  std::string because;
  for (const std::string& reason : why) because += (because.empty() ? "" : " and ") + reason;
  return because;
}

// Below the band: fail, unless the data leave room for P or only the finest level drops, from the
// band, at an error rounding may reach on a sensitive problem (a chaotic orbit's floor lies up to
// 10⁴ × the model).
Judgement judge_below(const Window& w) {
  const OrderAnalysis& a = w.a;
  const std::string ends = " (over " + std::to_string(a.fit.levels.size()) + " levels, " + window_ends(a) + "); ";
  if (const std::string because = room_for_p(w); !because.empty())
    return {CheckOutcome::inconclusive,
            "INCONCLUSIVE, fitted order " + w.order + " outside " + w.band + ", but " + because + ends +
                what_would_settle(a)};
  const std::size_t m = a.finest_orders.size();
  if (m >= 2 && a.finest_orders[m - 1] < a.finest_orders[m - 2] && a.finest_orders[m - 2] >= w.expected - w.tolerance &&
      a.finest_error_over_floor <= a.stall_reach)
    return {CheckOutcome::inconclusive,
            "INCONCLUSIVE, fitted order " + w.order + " outside " + w.band +
                printf_string(", but its finest order drops (%.3f -> %.3f) at an error only %.3g x its modelled floor, "
                              "where rounding may stop the convergence",
                              a.finest_orders[m - 2], a.finest_orders[m - 1], a.finest_error_over_floor) +
                ends + "a finer level would show whether the errors stall"};
  return {CheckOutcome::order_miss, "FAIL, fitted order " + w.order + " outside " + w.band + " (" + w.over + ")"};
}

// The judgement of one variable's window (check.hpp): its outcome and its finding after "name: ".
Judgement judge_window(const OrderAnalysis& a, double expected, double tolerance, double ratio) {
  const std::size_t n = a.fit.levels.size();
  const std::optional<LevelStatus> floor = floor_past_window(a);
  if (n < 3 && floor == LevelStatus::round_off)
    return {CheckOutcome::inconclusive,
            printf_string("INCONCLUSIVE, only %zu level(s) above the round-off floor, an order needs 3 (%s); double "
                          "precision cannot decide here: a coarser dt (more levels above the floor) or a longer t_end may",
                          n, window_ends(a).c_str())};
  if (n < 3 && floor == LevelStatus::reference)
    return {CheckOutcome::inconclusive,
            printf_string("INCONCLUSIVE, only %zu level(s) with an error at least %.0f x the reference's estimated error, an order "
                          "needs 3 (%s); the reference cannot decide here: a tighter reference (a smaller reference rtol) "
                          "or a coarser dt may",
                          n, kMinimumReferenceMargin, window_ends(a).c_str())};
  if (!a.fit.valid)
    return {CheckOutcome::no_order, printf_string("FAIL, only %zu level(s) in the asymptotic range: no order measured "
                                                  "(over all levels the error falls at order %.2f)",
                                                  n, a.overall_slope)};
  Window w{a, expected, tolerance, ratio, order_text(a.fit.value, expected, tolerance),
           printf_string("%.3f +/- %.3f", expected, tolerance), printf_string("over %zu levels", n)};
  if (a.fit.levels.front() > 0 && a.status[0] == LevelStatus::pre_asymptotic) {
    w.over += "; " + window_ends(a);
    w.ends_named = true;
  }
  if (std::abs(a.fit.value - expected) <= tolerance) return judge_within(w);
  if (a.fit.value > expected + tolerance)  // no order below P is seen
    return {CheckOutcome::inconclusive,
            "INCONCLUSIVE, fitted order " + w.order + " above " + w.band +
                ": the errors fall faster than order P here (its leading error term is not yet visible: a small "
                "error constant, or a method of higher order); no order below P is seen (" + w.over +
                (w.ends_named ? std::string() : ", " + window_ends(a)) + ")"};
  return judge_below(w);
}

// A level search's extrapolated order p∞ ± w for a variable whose fit did not settle: pass when
// the whole extrapolate lies in the band, |p∞ − P| + w ≤ tol; fail when it lies below P beyond
// its own half-width (P − p∞ > max(tol, w)); else (in the band but too wide, P within w, or above
// the band: no order below P seen) the data cannot decide.
Judgement judge_extrapolated(const OrderExtrapolation& x, double expected, double tolerance, double fitted) {
  const double miss = std::abs(x.value - expected);
  const CheckOutcome outcome = miss + x.half_width <= tolerance                              ? CheckOutcome::order_within
                               : miss <= std::max(tolerance, x.half_width) || x.value > expected ? CheckOutcome::inconclusive
                                                                                            : CheckOutcome::order_miss;
  const char* word = outcome == CheckOutcome::order_within ? "pass, "
                     : outcome == CheckOutcome::inconclusive ? "INCONCLUSIVE, "
                                                             : "FAIL, ";
  const std::string why = outcome != CheckOutcome::inconclusive ? ""
                          : x.value > expected + tolerance     ? ", but above it: no order below P is seen"
                          : miss <= tolerance                  ? ", but its half-width reaches outside the band"
                                                               : ", but the extrapolate's half-width covers it";
  return {outcome, word + describe(x) +
                       printf_string(" %s %.3f +/- %.3f (the fitted order %.3f did not settle)",
                                     miss <= tolerance ? "within" : "outside", expected, tolerance, fitted) +
                       why};
}

// A search stopped by a limit (budget, level or step limit) before the fit of variable v held
// `rules.min_fit_levels` levels has measured no order it can stand behind: the no_order finding,
// naming the stop; nullopt when the search stopped otherwise or the fit is long enough.
std::optional<Judgement> judge_coverage(const StudyResult& study, std::size_t v, const LevelSearch& search) {
  if (search.stop != SearchStop::budget && search.stop != SearchStop::level_limit && search.stop != SearchStop::step_limit)
    return std::nullopt;
  const auto needed = static_cast<std::size_t>(search.rules.min_fit_levels);
  if (study.orders[v].fit.levels.size() >= needed) return std::nullopt;
  return Judgement{CheckOutcome::no_order,
                   printf_string("FAIL, no order measured: the search stopped (%s) with %zu level(s) in the fit, fewer "
                                 "than the %zu an order's interval needs; %s",
                                 to_string(search.stop).c_str(), study.orders[v].fit.levels.size(), needed,
                                 search.reason.c_str())};
}

// The order judgement of variable v: exact, else the search's extrapolated order where one was
// made, else a search short of levels, else the window's.
Judgement judge_variable(const StudyResult& study, std::size_t v, double expected, double tolerance,
                         const LevelSearch* search) {
  const OrderAnalysis& a = study.orders[v];
  if (a.exact_to_round_off) return {CheckOutcome::exact, "pass, every level is exact to round-off"};
  if (search && v < search->extrapolations.size() && search->extrapolations[v] && search->extrapolations[v]->computed)
    return judge_extrapolated(*search->extrapolations[v], expected, tolerance, a.fit.value);
  if (search)
    if (std::optional<Judgement> short_of_levels = judge_coverage(study, v, *search)) return *short_of_levels;
  return judge_window(a, expected, tolerance, study.plan.ratio);
}

int severity(FindingResult r) { return r == FindingResult::fail ? 2 : r == FindingResult::inconclusive ? 1 : 0; }

}  // namespace

FindingResult result_of(CheckOutcome outcome) {
  switch (outcome) {
    case CheckOutcome::exact:
    case CheckOutcome::order_within:
    case CheckOutcome::constant_within: return FindingResult::pass;
    case CheckOutcome::inconclusive: return FindingResult::inconclusive;
    case CheckOutcome::order_miss:
    case CheckOutcome::no_order:
    case CheckOutcome::constant_outside: return FindingResult::fail;
  }
  return FindingResult::fail;
}

FindingResult CheckVerdict::worst() const {
  FindingResult worst = FindingResult::pass;
  for (const Finding& f : findings)
    if (severity(f.result()) > severity(worst)) worst = f.result();
  return worst;
}

int CheckVerdict::exit_code() const {
  switch (worst()) {
    case FindingResult::pass: return kExitDone;
    case FindingResult::inconclusive: return kExitInconclusive;
    case FindingResult::fail: return kExitCheckFailed;
  }
  return kExitCheckFailed;
}

bool CheckVerdict::has(CheckOutcome outcome) const {
  return std::any_of(findings.begin(), findings.end(), [outcome](const Finding& f) { return f.outcome == outcome; });
}

std::vector<std::string> CheckVerdict::lines() const {
  std::vector<std::string> lines;
  for (const Finding& f : findings) lines.push_back(f.line());
  return lines;
}

const Finding* CheckVerdict::find(std::size_t variable, Criterion criterion) const {
  for (const Finding& f : findings)
    if (f.variable == variable && f.criterion == criterion) return &f;
  return nullptr;
}

const Finding* CheckVerdict::worst_of(std::size_t variable) const {
  const Finding* worst = nullptr;
  for (const Finding& f : findings)
    if (f.variable == variable && (!worst || severity(f.result()) > severity(worst->result()))) worst = &f;
  return worst;
}

CheckVerdict check_orders(const StudyResult& study, double expected_order, double tolerance, const LevelSearch* search) {
  CheckVerdict verdict;
  verdict.expected_order = expected_order;
  verdict.tolerance = tolerance;
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const std::string& name = study.plan.variables[v].name;
    const auto own = study.plan.expected_order_by_variable.find(name);
    const double expected = own != study.plan.expected_order_by_variable.end() ? own->second : expected_order;
    verdict.expected_orders.push_back(expected);
    auto [outcome, text] = judge_variable(study, v, expected, tolerance, search);
    verdict.findings.push_back({v, name, Criterion::order, outcome, std::move(text)});
  }
  return verdict;
}

}  // namespace dlpverify
