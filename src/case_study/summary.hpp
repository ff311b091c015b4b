// The Markdown summary (--summary FILE of check and suite), for $GITHUB_STEP_SUMMARY and a
// merge request's comment: a heading with the verdict, then a table whose rows put what needs a
// look first — failures, then studies that ended without a verdict, then inconclusive ones, then
// passes, each group in its own order.
#pragma once

#include <string>
#include <vector>

#include "case_study/suite.hpp"

namespace dlpverify::case_study {

// A check's: one row per variable (verdict, variable, expected, fitted with its 95% interval, the
// finding's reason), or one ERROR row with `study.error` for a study that ended without a verdict.
std::string check_summary(const SuiteStudy& study);

// A suite's: the counts, then one row per study (verdict, study, and each variable's fitted order,
// or for a study that did not pass the reasons of the variables that did not).
std::string suite_summary(const std::vector<SuiteStudy>& studies);

// `text` in a Markdown table's cell: one line, |, the characters Markdown reads as emphasis, code
// or a link escaped with \, and & < > as entities (GitHub renders HTML in a summary).
std::string markdown_cell(const std::string& text);

}  // namespace dlpverify::case_study
