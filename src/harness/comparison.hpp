// `dlpverify compare A.json B.json` (docs/cli.md): two results of the same study (case,
// parameters, reference and levels; the integrator may differ), level by level, and a verdict.
// B is judged against A as against a baseline: they agree when every variable's fitted orders are
// within the order tolerance of each other and its error constants within the constant band
// (harness/constant_gate.hpp), or the variable is exact to round-off in both.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/constant_gate.hpp"
#include "dlpverify/recorded_study.hpp"

namespace dlpverify {

struct ComparisonTolerances {
  double order = 0.1;                               // |p_B − p_A|, as check's --order-tolerance
  double constant = kDefaultConstantTolerance;      // |C_B − C_A| ≤ this × C_A
};

struct VariableComparison {
  std::string name;
  bool orders_agree = false;
  std::string order_text;         // "fitted order 2.038 and 2.035 (difference -0.003, within 0.1)"
  ConstantComparison constant;    // B's against A's
  bool agree() const { return orders_agree && constant.agree; }
};

struct StudyComparison {
  bool agree = true;                          // every variable agrees
  ComparisonTolerances tolerances;
  std::vector<VariableComparison> variables;  // in A's order
};

// InputError (a whole message naming both files and what differs) when B is not a result of A's study.
StudyComparison compare_studies(const RecordedStudy& a, const RecordedStudy& b, const ComparisonTolerances& tolerances);

// The console report: both files and integrators, per variable the levels' errors A and B, their
// ratio B/A and pairwise orders, the fitted orders and constants, then the verdict line.
std::string format_comparison(const RecordedStudy& a, const RecordedStudy& b, const StudyComparison& comparison);

// The comparison as JSON (`compare --json`): both files and integrators, the study's identity,
// the tolerances, per variable the levels (dt, steps, error_a, error_b, ratio = B/A, pairwise
// orders), the fitted orders and their difference, the error constants and their ratio and
// change (B/A − 1), whether it agrees; then `agree`, `verdict` ("AGREE" or "DIFFER") and the
// disagreements, each as the report words it.
nlohmann::json comparison_json(const RecordedStudy& a, const RecordedStudy& b, const StudyComparison& comparison);

}  // namespace dlpverify
