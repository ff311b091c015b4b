#include "case_study/suite.hpp"

#include <algorithm>
#include <cmath>

#include "case_study/ci_report.hpp"
#include "io/format.hpp"
#include "io/printable.hpp"

namespace dlpverify::case_study {

using Result = VariableVerdict::Result;

const char* variable_verdict_word(Result r) { return r == Result::pass ? "pass" : r == Result::fail ? "FAIL" : "INCONCLUSIVE"; }

std::string fitted_text(const OrderFit& fit) {
  if (!fit.valid) return "-";
  std::string text = printf_string("%.3f", fit.value);
  if (std::isfinite(fit.ci_low) && std::isfinite(fit.ci_high)) text += printf_string(" [%.3f, %.3f]", fit.ci_low, fit.ci_high);
  return text;
}

// A study file's name, a label, an error line as a console cell: shown as stderr shows it, never
// obeyed by the terminal (ESC, BEL) and never breaking the row (a line break in a file name).
namespace {
std::string cell(const std::string& text) { return printable(text, std::string_view::npos); }
}  // namespace

// What a finding says after its verdict word ("pass, fitted order …" → "fitted order …").
std::string reason_of(const std::string& finding) {
  const std::string::size_type comma = finding.find(", ");
  return comma == std::string::npos ? finding : finding.substr(comma + 2);
}

std::string suite_table(const std::vector<SuiteStudy>& studies) {
  std::size_t width = 5, variable_width = 8;
  for (const SuiteStudy& s : studies) {
    width = std::max(width, cell(s.name).size());
    if (s.outcome)
      for (const VariableVerdict& v : s.outcome->verdicts) variable_width = std::max(variable_width, cell(v.variable).size());
  }
  const auto row = [&](const std::string& study, const std::string& variable, const std::string& expected,
                       const std::string& fitted, const std::string& verdict, const std::string& reason) {
    return printf_string("%-*s  %-*s  %8s  %-24s %-12s %s\n", static_cast<int>(width), cell(study).c_str(),
                         static_cast<int>(variable_width), cell(variable).c_str(), expected.c_str(), fitted.c_str(),
                         verdict.c_str(), cell(reason).c_str());
  };
  std::string table = row("study", "variable", "expected", "fitted [95% interval]", "verdict", "reason");
  for (const SuiteStudy& s : studies) {
    if (!s.outcome) {
      table += row(s.name, "-", "-", "-", study_verdict_word(s.code), s.error);
      continue;
    }
    for (const VariableVerdict& v : s.outcome->verdicts)
      table += row(s.name, v.variable, value_text(v.expected), fitted_text(v.fit), variable_verdict_word(v.result), reason_of(v.finding));
  }
  const std::string failures = suite_failures(studies);
  return table + "\n" + suite_counts(studies) + "\n" + (failures.empty() ? "" : failures + "\n");
}

int suite_rank(const SuiteStudy& study) {
  switch (study.exit_code()) {
    case kExitDone: return 3;
    case kExitCheckFailed: return 0;
    case kExitInconclusive: return 2;
    default: return 1;
  }
}

std::string suite_failures(const std::vector<SuiteStudy>& studies) {
  const char* words[] = {"failed", "no verdict", "inconclusive"};
  std::string line;
  for (int rank = 0; rank < 3; ++rank) {
    std::string names;
    for (const SuiteStudy& s : studies)
      if (suite_rank(s) == rank) names += (names.empty() ? "" : ", ") + cell(s.name);
    if (!names.empty()) line += (line.empty() ? "" : "; ") + std::string(words[rank]) + ": " + names;
  }
  return line;
}

std::string study_verdict_word(int exit_code) {
  switch (exit_code) {
    case kExitDone: return "pass";
    case kExitCheckFailed: return "FAIL";
    case kExitInconclusive: return "INCONCLUSIVE";
    default: return printf_string("ERROR (exit %d)", exit_code);
  }
}

std::string suite_counts(const std::vector<SuiteStudy>& studies) {
  int counts[3] = {0, 0, 0}, errors = 0;  // pass, inconclusive, fail: FindingResult's order
  for (const SuiteStudy& s : studies)
    if (!s.outcome)
      ++errors;
    else
      for (const VariableVerdict& v : s.outcome->verdicts) ++counts[static_cast<int>(v.result)];
  return printf_string("%zu stud%s: %d variable%s pass, %d fail, %d inconclusive; %d stud%s ended without a verdict",
                       studies.size(), studies.size() == 1 ? "y" : "ies", counts[0], counts[0] == 1 ? "" : "s", counts[2],
                       counts[1], errors, errors == 1 ? "y" : "ies");
}

int suite_exit_code(const std::vector<SuiteStudy>& studies) {
  for (const int code : {kExitBadInput, kExitSolverFailed, kExitOutputFailed, kExitCheckFailed, kExitInconclusive})
    for (const SuiteStudy& s : studies)
      if (s.exit_code() == code) return code;
  return kExitDone;
}

std::vector<JunitSuite> suite_junit(const std::vector<SuiteStudy>& studies) {
  std::vector<JunitSuite> suites;
  for (const SuiteStudy& s : studies)
    suites.push_back(s.outcome ? junit_suite(s.name, *s.outcome) : junit_error_suite(s.name, s.code, s.error, s.seconds));
  return suites;
}

}  // namespace dlpverify::case_study
