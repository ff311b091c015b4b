// A suite: many checks in one command, one summary, one exit code, one JUnit XML report
// (docs/cli.md, "dlpverify suite"). The command runs each study and hands its outcome, or the
// failure that ended it, here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "case_study/outcome.hpp"
#include "io/junit_xml.hpp"

namespace dlpverify::case_study {

// One study of a suite: its outcome when it ran to a verdict, else the exit code and line of
// what ended it (bad input 2, a solver's failure 3, an output not written 4).
struct SuiteStudy {
  std::string name;  // its study file's name, without folder and .toml ("drag-rk2", "drag-rk2 (2)")
  std::string file;  // its study file, as given
  std::optional<CaseOutcome> outcome;
  int code = kExitDone;
  std::string error;
  double seconds = 0.0;
  int exit_code() const { return outcome ? outcome->exit_code : code; }
};

// How a variable's verdict reads: "pass", "FAIL" or "INCONCLUSIVE".
const char* variable_verdict_word(VariableVerdict::Result result);
// "2.023 [2.008, 2.039]": a fitted order and its 95% interval, the interval only where the fit has
// one (three levels or more); "-" without a fit.
std::string fitted_text(const OrderFit& fit);
// What a finding says after its verdict word ("pass, fitted order …" → "fitted order …").
std::string reason_of(const std::string& finding);

// How a study that ended with `exit_code` reads, as a finding does: "pass", "FAIL", "INCONCLUSIVE"
// or "ERROR (exit N)".
std::string study_verdict_word(int exit_code);

// "4 studies: 2 variables pass, 2 fail, 2 inconclusive; 1 study ended without a verdict".
std::string suite_counts(const std::vector<SuiteStudy>& studies);

// The studies that did not pass, by name, the worst first: "failed: a, b; no verdict: c;
// inconclusive: d" (a study's rank: suite_rank); "" when every study passed.
std::string suite_failures(const std::vector<SuiteStudy>& studies);

// Where a study is listed: 0 failed, 1 ended without a verdict, 2 inconclusive, 3 passed.
int suite_rank(const SuiteStudy& study);

// The summary: one row per study and variable (study, variable, expected order, fitted order with
// its 95% interval, verdict, the finding), one per study that ended without a verdict, then the
// counts, and last the names of the studies that did not pass (suite_failures).
std::string suite_table(const std::vector<SuiteStudy>& studies);

// The suite's exit code: 0 when every study passed; else the first of 2 (a study file is bad
// input), 3 (a solver failed), 4 (an output was not written), 1 (a check failed), 5 (a check
// could not decide) that some study ended with — what must be fixed before the verdicts count
// comes first.
int suite_exit_code(const std::vector<SuiteStudy>& studies);

// One JUnit test suite per study (junit_suite, or junit_error_suite for one without a verdict).
std::vector<JunitSuite> suite_junit(const std::vector<SuiteStudy>& studies);

}  // namespace dlpverify::case_study
