// What a case study leaves its caller to print, after every output file is written.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/order.hpp"

namespace dlpverify::case_study {

// One measured variable's verdict, as a suite's summary and a CI report (JUnit XML) list it.
struct VariableVerdict {
  using Result = FindingResult;
  std::string variable;     // the study's name for it ("position")
  Result result = Result::pass;  // the worst of its findings: fail over inconclusive over pass
  double expected = 0.0;    // P, its own or the study's
  double tolerance = 0.0;   // it passes when |fitted − expected| ≤ this
  OrderFit fit;             // the fitted order and its 95% interval (over the asymptotic window)
  ErrorConstant constant;   // C of e ≈ C Δt^P over the fit's levels (invalid without one)
  std::string finding;      // the line of its worst finding, without the variable's name
  // What is fitted and expected: "order", or "exponent" for a sweep of --tolerances (e ≈ C rtol^E).
  std::string quantity = "order";
};

struct CaseOutcome {
  CaseOutcome() = default;
  CaseOutcome(int code, std::string table_printed) : exit_code(code), console(std::move(table_printed)) {}

  int exit_code = kExitDone;  // docs/verification.md, "Exit codes"; 128 + N when signal N stopped the study
  // The console table; empty when an output goes to standard output instead, on a rank other than
  // 0 (the command's outcome is rank 0's) and when a signal stopped the study.
  std::string console;
  // A check's verdict per variable (empty for converge), the study's table and JSON result, what
  // it ran ("drag rk2": the case and the integrator) and how long it took [s].
  std::vector<VariableVerdict> verdicts;
  std::string table;
  nlohmann::json report;
  std::string study;
  double seconds = 0.0;
};

}  // namespace dlpverify::case_study
