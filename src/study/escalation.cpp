#include "study/escalation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "dlpverify/butcher_method.hpp"
#include "dlpverify/extended_runge_kutta.hpp"
#include "dlpverify/extended_study.hpp"
#include "dlpverify/level_search.hpp"
#include "harness/distribution.hpp"
#include "io/format.hpp"

namespace dlpverify {

namespace {

// Rank 0's worst finding, shared: 0 pass, 1 inconclusive, 2 fail.
long shared_worst(const StudyOutcome& outcome) {
  long worst = 0;
  if (outcome.reported && outcome.verdict) {
    const FindingResult result = outcome.verdict->worst();
    worst = result == FindingResult::fail ? 2 : result == FindingResult::inconclusive ? 1 : 0;
  }
  return distribution().max(worst);  // the other ranks give 0
}

// Whether the finding's variable has levels at double's round-off floor or the reference's accuracy:
// finer levels in double cannot go on, extended precision can.
bool limited_by_floor(const StudyResult& study, const Finding& finding) {
  for (const LevelStatus status : study.orders.at(finding.variable).status)
    if (status == LevelStatus::round_off || status == LevelStatus::reference) return true;
  return false;
}

// Rank 0's undecided findings, those whose variable reached a floor (`at_floor`) or those of
// variables that did not.
std::vector<std::string> undecided_findings(const StudyOutcome& outcome, bool at_floor) {
  std::vector<std::string> lines;
  if (outcome.reported && outcome.verdict)
    for (const Finding& finding : outcome.verdict->findings)
      if (finding.result() == FindingResult::inconclusive && limited_by_floor(outcome.result, finding) == at_floor)
        lines.push_back(finding.line());
  return lines;
}

// Why nothing the tool controls can take the study beyond double (empty: extended precision can).
std::string why_not(const StudyRequest& request, const std::string& extended_refusal) {
  if (request.reference.kind == ReferenceKind::manufactured)
    return "a manufactured solution is evaluated in double only, and so are the levels compared with it";
  return extended_refusal;
}

// The request of the escalated study in extended precision against the extended reference:
// `first`'s levels from its coarsest, as fixed levels (a search's levels are taken as they were).
StudyRequest extended_request(const StudyRequest& request, const StudyResult& first) {
  StudyRequest extended = request;
  extended.search.reset();
  extended.plan.precision = Precision::extended;
  extended.plan.coarsest_dt = first.levels.front().dt;
  extended.plan.ratio = first.plan.ratio;
  extended.plan.levels = std::max(2, static_cast<int>(first.levels.size()));
  extended.reference.kind = ReferenceKind::extended;
  extended.history_outputs = 0;  // the history and the per-member view stay the first study's
  extended.keep_member_states = false;
  return extended;
}

// The request of the escalated study with finer levels: a level search from the same coarsest
// level, by its default rules within the escalation's budget. The search, not a fixed count of
// levels more, because its rules end on the levels where the orders settle and never judge by the
// levels where the errors stall above the modelled floor (a chaotic orbit's fifth-order methods
// fail on eight fixed levels there).
StudyRequest search_request(const StudyRequest& request, const StudyResult& first) {
  StudyRequest searched = request;
  searched.search.emplace();
  searched.search->budget_seconds = request.escalation_budget_seconds;
  searched.plan.coarsest_dt = first.levels.front().dt;
  searched.plan.ratio = first.plan.ratio;
  searched.history_outputs = 0;
  searched.keep_member_states = false;
  return searched;
}

// The levels an escalation adds to the first study's before it asks whether more are worth it: its
// finest level then takes 2^4 times the first study's finest steps (at ratio 2), where the DLP
// cases' fifth-order methods settle by three. Past them it goes on only while still_settling.
constexpr int kMostExtraLevels = 4;

// Whether every undecided variable's finest pairwise order is closer to P than the one before, by
// more than a tenth of the tolerance: its errors are still approaching the asymptotic range, and
// another level may settle what four more did not (Cash–Karp on the Prothero–Robinson equation:
// 5.3, 5.2, … towards 5). An order that stays where it is (a method of higher order on this
// problem, or one that has settled off P) shows nothing new at a finer level, and ends it.
bool still_settling(const StudyOutcome& outcome) {
  bool settling = false;
  if (outcome.reported && outcome.verdict) {
    const CheckVerdict& verdict = *outcome.verdict;
    settling = true;
    for (const Finding& finding : verdict.findings) {
      if (finding.result() != FindingResult::inconclusive) continue;
      std::vector<double> orders;
      for (const auto& order : outcome.result.orders.at(finding.variable).pairwise)
        if (order) orders.push_back(*order);
      const double P = finding.variable < verdict.expected_orders.size() ? verdict.expected_orders[finding.variable]
                                                                          : verdict.expected_order;
      const std::size_t n = orders.size();
      settling = settling && n >= 2 &&
                 std::abs(orders[n - 1] - P) < std::abs(orders[n - 2] - P) - verdict.tolerance / 10.0;
    }
  }
  return distribution().any(settling);  // rank 0's
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string escalation_refusal(const Problem& problem, const Integrator& integrator) {
  const std::string refusal = extended_refusal(problem, integrator);
  if (!refusal.empty()) return refusal;
  if (!read_exactly(dynamic_cast<const ButcherMethod&>(integrator).butcher()))
    return integrator.name() + "'s coefficients are not all fractions of denominators up to 2^24: held as doubles, "
                               "they miss its order conditions by about 1e-17, a floor extended precision cannot lower";
  return "";
}

namespace {

// Runs `escalated` one level more each round until its verdict is decided, and the same, at two
// level counts in a row, or kMostExtraLevels past the first study's and no longer still_settling,
// or kMostLevels, or the budget is spent. The levels finished are taken over (StudyProgress): a
// round costs its finest level, about r times the round before. Before each level the budget is
// asked again, that level's cost taken as r times the level before's, so a round that cannot
// finish in it does not start its finest level (double-double costs 3 to 260 times the double
// levels, by how the double path was vectorised: docs/performance.md). Empty: no round finished
// within the budget.
std::optional<JudgedStudy> refine_until_decided(StudyRequest escalated, const JudgeStudy& judge,
                                                const std::function<bool()>& stop, double budget_seconds,
                                                Escalation& escalation) {
  std::vector<LevelResult> kept;
  const auto start = std::chrono::steady_clock::now();
  bool over_budget = false;
  double level_seconds = 0.0;  // the last level finished
  StudyProgress progress;
  progress.finished = [&](const LevelResult& level) {
    kept.push_back(level);
    level_seconds = level.wall_seconds;
  };
  progress.stop = [&] {
    if (stop && stop()) return true;
    over_budget = distribution().any(seconds_since(start) + escalated.plan.ratio * level_seconds > budget_seconds);
    return over_budget;
  };
  const int settled_only_from = escalated.plan.levels + kMostExtraLevels;  // levels past it need still_settling
  long previous = -1;
  std::optional<JudgedStudy> round;
  for (;;) {
    progress.done = kept;
    const auto round_start = std::chrono::steady_clock::now();
    try {
      round = judge(escalated, progress);
    } catch (const StudyStopped&) {
      if (!over_budget) throw StudyStopped(escalation.double_levels);  // the first study's levels are its journal's
      escalation.budget_spent = true;
      if (round) --escalated.plan.levels;  // the round before stands
      break;
    }
    const long worst = shared_worst(round->outcome);
    const double round_seconds = distribution().max(seconds_since(round_start));
    const double spent = distribution().max(seconds_since(start));
    if (worst != 1 && worst == previous) break;  // decided, and confirmed at one more level
    escalation.budget_spent = spent + escalated.plan.ratio * round_seconds > budget_seconds;
    if (escalation.budget_spent || escalated.plan.levels >= kMostLevels) break;
    if (escalated.plan.levels >= settled_only_from && !still_settling(round->outcome)) break;
    previous = worst;
    ++escalated.plan.levels;
  }
  escalation.seconds = distribution().max(seconds_since(start));
  if (!round) return round;
  escalation.ran = true;
  escalation.levels = escalated.plan.levels;
  return round;
}

// The study searched from the coarsest level of `first` (search_request): its outcome, with what ran.
StudyOutcome searched_finer(const StudyRequest& request, const StudyResult& first, const JudgeStudy& judge,
                            const std::function<bool()>& stop, Escalation escalation) {
  StudyProgress progress;
  progress.stop = stop;
  const auto start = std::chrono::steady_clock::now();
  JudgedStudy searched;
  try {
    searched = judge(search_request(request, first), progress);
  } catch (const StudyStopped&) {
    throw StudyStopped(escalation.double_levels);  // the first study's levels, all finished, are its journal's
  }
  escalation.ran = true;
  escalation.levels = static_cast<int>(distribution().max(static_cast<long>(searched.outcome.result.levels.size())));
  escalation.seconds = distribution().max(seconds_since(start));
  escalation.budget_spent = distribution().any(searched.outcome.search && searched.outcome.search->stop == SearchStop::budget);
  searched.outcome.escalation = std::move(escalation);
  return std::move(searched.outcome);
}

// The study run again beyond double from `first`'s levels (extended_request), within what is left
// of the budget; `fallback` stands, with why, when no round finished (`first` may be its result:
// it is moved only then, after every use of `first`).
StudyOutcome beyond_double(const StudyRequest& request, const StudyResult& first, const JudgeStudy& judge,
                           const std::function<bool()>& stop, Escalation escalation, StudyOutcome&& fallback) {
  const double budget = request.escalation_budget_seconds - escalation.searched_seconds;
  std::optional<JudgedStudy> last = refine_until_decided(extended_request(request, first), judge, stop, budget, escalation);
  if (!last) {
    escalation.not_possible = printf_string("its budget of %.3g s was spent before the extended study's levels finished "
                                            "(StudyRequest::escalation_budget_seconds)", request.escalation_budget_seconds);
    fallback.escalation = std::move(escalation);
    return std::move(fallback);
  }
  last->outcome.escalation = std::move(escalation);
  return std::move(last->outcome);
}

}  // namespace

StudyOutcome escalate(const StudyRequest& request, JudgedStudy first, const JudgeStudy& judge,
                      const std::function<bool()>& stop) {
  StudyOutcome& outcome = first.outcome;
  if (!request.check || !request.escalate || shared_worst(outcome) != 1 || outcome.result.levels.empty())
    return std::move(outcome);
  Escalation escalation;
  escalation.double_levels = static_cast<int>(outcome.result.levels.size());
  escalation.double_findings = undecided_findings(outcome, true);
  const std::string not_possible = why_not(request, first.extended_refusal);
  if (distribution().any(!escalation.double_findings.empty())) {
    escalation.not_possible = not_possible;
    if (!escalation.not_possible.empty()) {
      outcome.escalation = std::move(escalation);
      return std::move(outcome);
    }
    return beyond_double(request, outcome.result, judge, stop, std::move(escalation), std::move(outcome));
  }
  // Undecided above every floor: finer levels decide, in the same arithmetic (a search runs in
  // double only). A level search chose its levels already and says why it stopped.
  if (request.search || request.plan.precision != Precision::double_precision) return std::move(outcome);
  escalation.means = Escalation::Means::finer_levels;
  escalation.double_findings = undecided_findings(outcome, false);
  StudyOutcome searched = searched_finer(request, outcome.result, judge, stop, std::move(escalation));
  // The search's finer levels reached a floor undecided: beyond double from its levels, when the
  // tool can step the method there.
  if (shared_worst(searched) != 1 || !not_possible.empty() || !distribution().any(!undecided_findings(searched, true).empty()))
    return searched;
  Escalation chained = *searched.escalation;
  chained.means = Escalation::Means::extended_precision;
  chained.searched_levels = chained.levels;
  chained.searched_seconds = chained.seconds;
  chained.ran = false;
  return beyond_double(request, searched.result, judge, stop, std::move(chained), std::move(searched));
}

}  // namespace dlpverify
