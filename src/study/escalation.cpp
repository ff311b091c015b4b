#include "study/escalation.hpp"

#include <algorithm>
#include <chrono>

#include "dlpverify/butcher_method.hpp"
#include "dlpverify/extended_runge_kutta.hpp"
#include "dlpverify/extended_study.hpp"
#include "harness/distribution.hpp"

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

// Rank 0's findings that could not decide because of a floor, shared as whether there are any.
std::vector<std::string> floor_limited_findings(const StudyOutcome& outcome) {
  std::vector<std::string> lines;
  if (outcome.reported && outcome.verdict)
    for (const Finding& finding : outcome.verdict->findings)
      if (finding.result() == FindingResult::inconclusive && limited_by_floor(outcome.result, finding))
        lines.push_back(finding.line());
  return lines;
}

// Why nothing the tool controls can take the study beyond double (empty: extended precision can).
std::string why_not(const StudyRequest& request, const std::string& extended_refusal) {
  if (request.reference.kind == ReferenceKind::manufactured)
    return "a manufactured solution is evaluated in double only, and so are the levels compared with it";
  return extended_refusal;
}

// The request of the escalated study: `first`'s levels from its coarsest, in extended precision
// against the extended reference, fixed levels (a search's levels are taken as they were).
StudyRequest extended_request(const StudyRequest& request, const StudyResult& first) {
  StudyRequest extended = request;
  extended.search.reset();
  extended.plan.precision = Precision::extended;
  extended.plan.coarsest_dt = first.levels.front().dt;
  extended.plan.ratio = first.plan.ratio;
  extended.plan.levels = std::max(2, static_cast<int>(first.levels.size()));
  extended.reference.kind = ReferenceKind::extended;
  extended.history_outputs = 0;  // the history and the per-member view stay the double study's
  extended.keep_member_states = false;
  return extended;
}

// The most levels an escalation adds to the double study's: its finest level then takes 2^4 times
// the double study's finest steps (at ratio 2), where the DLP cases' fifth-order methods settle by
// three, and a finding that stays undecided there (an order above P that extended precision shows
// as clearly as double) is not worth more.
constexpr int kMostExtraLevels = 4;

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

StudyOutcome escalate(const StudyRequest& request, JudgedStudy first, const JudgeStudy& judge,
                      const std::function<bool()>& stop) {
  StudyOutcome& outcome = first.outcome;
  if (!request.check || !request.escalate || shared_worst(outcome) != 1) return std::move(outcome);
  Escalation escalation;
  escalation.double_findings = floor_limited_findings(outcome);
  // Undecided above both floors: finer levels in double decide (the verdict says so), not another arithmetic.
  if (!distribution().any(!escalation.double_findings.empty())) return std::move(outcome);
  escalation.double_levels = static_cast<int>(outcome.result.levels.size());
  escalation.not_possible = why_not(request, first.extended_refusal);
  if (!escalation.not_possible.empty() || outcome.result.levels.empty()) {
    outcome.escalation = std::move(escalation);
    return std::move(outcome);
  }

  // One level more each round, the finished levels taken over (StudyProgress): a round costs its
  // finest level, about r times the round before.
  StudyRequest extended = extended_request(request, outcome.result);
  std::vector<LevelResult> kept;
  StudyProgress progress;
  progress.stop = stop;
  progress.finished = [&kept](const LevelResult& level) { kept.push_back(level); };
  const int most_levels = extended.plan.levels + kMostExtraLevels;
  const auto start = std::chrono::steady_clock::now();
  long previous = -1;
  for (;;) {
    progress.done = kept;
    const auto round_start = std::chrono::steady_clock::now();
    try {
      first = judge(extended, progress);
    } catch (const StudyStopped&) {
      throw StudyStopped(escalation.double_levels);  // the double study's levels, all finished, are its journal's
    }
    const long worst = shared_worst(first.outcome);
    const double round = distribution().max(seconds_since(round_start));
    const double spent = distribution().max(seconds_since(start));
    if (worst != 1 && worst == previous) break;  // decided, and confirmed at one more level
    escalation.budget_spent = spent + extended.plan.ratio * round > request.escalation_budget_seconds;
    if (escalation.budget_spent || extended.plan.levels == std::min(kMostLevels, most_levels)) break;
    previous = worst;
    ++extended.plan.levels;
  }
  escalation.ran = true;
  escalation.levels = extended.plan.levels;
  escalation.seconds = distribution().max(seconds_since(start));
  first.outcome.escalation = std::move(escalation);
  return std::move(first.outcome);
}

}  // namespace dlpverify
