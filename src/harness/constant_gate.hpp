// The error constant as a gate (docs/verification.md, "The error constant as a gate"): a
// variable's C of e ≈ C Δt^p against a baseline's, |C − C_base| ≤ tolerance × C_base. The
// constant moves where the order does not: a wrong weight in an order-2 family keeps p = 2.
#pragma once

#include <map>
#include <string>

#include "dlpverify/check.hpp"
#include "dlpverify/recorded_study.hpp"

namespace dlpverify {

// One variable's constant beside the baseline's.
struct ConstantComparison {
  bool agree = false;
  double ratio = 0.0;  // C / C_base; NaN when either has none
  std::string text;    // "error constant 6.25e-02 outside 9.375e-02 +/- 5% (band [...], ratio 0.667)"
};

// `now` against `base` (the same variable): within the band, or both exact to round-off, agree;
// a constant on one side only, or constants at two orders p, do not.
ConstantComparison compare_constants(const RecordedVariable& base, const RecordedVariable& now, double tolerance);

// The baseline is of this study: the same case, parameters, reference and levels, and constants
// fitted at `expected_order`, or at a variable's own in `by_variable`. Otherwise
// InputError(quantity, baseline.source, what differs).
void require_baseline_of(const RecordedStudy& now, const RecordedStudy& baseline, double expected_order,
                         const std::map<std::string, double>& by_variable, const std::string& quantity);

// One finding per variable of `now` (outcome constant_within or constant_outside) appended to
// `verdict`, which fails when any constant leaves its band.
void check_constants(const RecordedStudy& now, const RecordedStudy& baseline, double tolerance, CheckVerdict& verdict);

}  // namespace dlpverify
