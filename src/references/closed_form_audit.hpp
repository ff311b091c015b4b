// The audit of a closed form: trusted only after it proves itself (docs/model.md §4).
//
//   (a) ODE residual — its time derivative by an 8th-order central difference against the
//       problem's right-hand side, at several times, every member (harness/ode_residual.hpp);
//   (b) CVODE distance — relative L2 distance from CVODE (Adams, rtol 1e-12, restarted at every
//       kink) on the same members and times, per measured variable.
// A closed form passes when (a) ≤ 1e-8 and (b) ≤ 1e-9. Any problem with a closed form can be
// audited; the DLP's cases and the source paper's published formulas are (the audit command).
#pragma once

#include <string>
#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

struct AuditThresholds {
  double residual = 1e-8;
  double cvode_distance = 1e-9;
};

struct BaselineAudit {
  std::string baseline;       // the case's name, or the published formula's
  bool published = false;     // one of the source paper's formulas (expected to fail)
  std::string source;         // the formula and where it comes from
  int particles = 0;          // members audited
  std::vector<double> times;  // τ audited
  double residual = 0.0;        // largest finite relative ODE residual
  double cvode_distance = 0.0;  // largest finite relative L2 distance from CVODE
  int non_finite = 0;           // residuals or distances that were NaN or infinite (a failure)
  bool passed = false;
};

// Audits `sample`'s closed form at τ = ¼, ½ and 1 × t_end on its initial state. Throws
// InputError when it has no closed form. baseline, published and source are the caller's.
BaselineAudit audit_closed_form(const Problem& sample, double t_end, const AuditThresholds& thresholds = {});

}  // namespace dlpverify
