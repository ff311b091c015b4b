// The rule every sweep of tolerances keeps: a CVODE reference at the sweep's own tolerance would
// measure the tightest runs against themselves (Adams reproduces its own result bit for bit), so
// it must be at least a decade tighter than the tightest rtol.
#pragma once

#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "io/format.hpp"

namespace dlpverify {

// Throws InputError naming the "reference relative tolerance" when `reference` breaks the rule.
inline void check_reference_below(const ReferenceSettings& reference, double tightest_rtol) {
  const double loosest = tightest_rtol / 10.0;
  if (reference.kind == ReferenceKind::cvode && reference.rtol > loosest * (1.0 + 1e-9))
    throw InputError("reference relative tolerance", value_text(reference.rtol),
                     "must be at most the tightest rtol / 10 = " + value_text(loosest) +
                         ", or the tightest runs measure the reference against itself");
}

}  // namespace dlpverify
