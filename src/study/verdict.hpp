// The verdict on a study, judged once for every command and every API user (docs/verification.md,
// "The verdict"): the fitted orders against the expected order, a level search's extrapolated
// orders and its coverage, the error constants against a baseline; and, when it fails, the reasons
// the study and the problem show.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "dlpverify/level_search.hpp"
#include "dlpverify/missed_order.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/recorded_study.hpp"

namespace dlpverify {

// The orders of `study` against `order` ± `tolerance` (check_orders); with a level search (`search`
// not null) its variables whose order was extrapolated are judged by that order and a search that
// stopped short of a fit fails them (judge_search_coverage); with a baseline each error constant
// must stay within `constant_tolerance` of the baseline's (check_constants). A baseline of another
// study is an InputError naming "baseline".
CheckVerdict judge_study(const StudyDescription& description, const StudyResult& study, double order, double tolerance,
                         const LevelSearch* search, const RecordedStudy* baseline, double constant_tolerance);

// A finished study's report: the console table and the JSON result.
struct StudyReport {
  std::string table;
  nlohmann::json result;
};

// The report of format_table and to_json, with the level search (when `search` is not null) and,
// when the verdict failed, every reason `context` and the search's extrapolations show for it.
StudyReport study_report(const StudyDescription& description, const StudyResult& study,
                         const std::optional<CheckVerdict>& verdict, const LevelSearch* search,
                         const std::optional<MissContext>& context);

}  // namespace dlpverify
