// What a check does when its study could not decide (StudyRequest::escalate). Where some
// undecided variable reached double's round-off floor or the reference's accuracy, it runs the
// study again in extended precision, where the tool can step the integrator and the problem there,
// refining level by level until the verdict is the same decided one at two level counts in a row —
// the confirmation a level search asks too — or the budget is spent. Where none did, a level search
// from the same coarsest level takes finer levels in double (docs/verification.md, "Escalation").
#pragma once

#include <functional>
#include <string>

#include "dlpverify/study_request.hpp"

namespace dlpverify {

// Why the study of `integrator` on `problem` cannot escalate to extended precision (empty: it can):
// extended_refusal's reasons, and a tableau whose coefficients are not all small fractions.
std::string escalation_refusal(const Problem& problem, const Integrator& integrator);

// A study solved, described and judged, its report not yet written (run()).
struct JudgedStudy {
  StudyOutcome outcome;
  std::string extended_refusal;  // escalation_refusal: why it cannot escalate; empty: it can
};

// Solves and judges one request, its levels continued from `progress` as run() does.
using JudgeStudy = std::function<JudgedStudy(const StudyRequest&, const StudyProgress&)>;

// `first`'s outcome when its check decided, escalation is off or it ran no check; else the outcome
// of the escalated study (judged by `judge`, asked to stop by `stop` before each level), or
// `first`'s when no escalation is possible, with Escalation saying what was done or why not. Every
// rank takes part; the decisions are rank 0's.
StudyOutcome escalate(const StudyRequest& request, JudgedStudy first, const JudgeStudy& judge,
                      const std::function<bool()>& stop);

}  // namespace dlpverify
