#include "study/verdict.hpp"

#include "harness/constant_gate.hpp"

namespace dlpverify {

CheckVerdict judge_study(const StudyDescription& description, const StudyResult& study, double order, double tolerance,
                         const LevelSearch* search, const RecordedStudy* baseline, double constant_tolerance) {
  CheckVerdict verdict = check_orders(study, order, tolerance, search);
  if (baseline) {
    const RecordedStudy now = recorded_study(description, study, "this study");
    require_baseline_of(now, *baseline, order, study.plan.expected_order_by_variable, "baseline");
    check_constants(now, *baseline, constant_tolerance, verdict);
  }
  return verdict;
}

StudyReport study_report(const StudyDescription& description, const StudyResult& study,
                         const std::optional<CheckVerdict>& verdict, const LevelSearch* search,
                         const std::optional<MissContext>& context) {
  StudyReport report{format_table(description, study, verdict), to_json(description, study, verdict)};
  if (search) {
    report.table = format_level_search(*search, study) + "\n" + report.table;
    report.result["level_search"] = to_json(*search, study);
  }
  if (verdict && !verdict->passed() && context) {
    MissContext miss = *context;
    if (search)
      for (const std::optional<OrderExtrapolation>& x : search->extrapolations)
        miss.extrapolation.push_back(x ? describe(*x) : std::string());
    const auto reasons = explain_missed_orders(study, *verdict, miss);
    report.table += format_missed_orders(study, reasons);
    report.result["missed_order"] = to_json(study, miss, reasons);
  }
  return report;
}

}  // namespace dlpverify
