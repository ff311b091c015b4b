// The baseline audit: a closed form is trusted only after it proves itself (SPEC §4).
//
//   (a) ODE residual — its time derivative by an 8th-order central difference against the DLP
//       right-hand side, at several times and particles (exact::ode_residual);
//   (b) CVODE distance — relative L2 distance from CVODE (Adams, rtol 1e-12) on the same particles
//       and times, per measured variable.
// A closed form passes when (a) ≤ 1e-8 and (b) ≤ 1e-9. The seed's published formulas (its eqs. 23
// and 26) are audited beside them and must be seen failing, so users see why the corrected forms
// of SPEC §4 exist.
#pragma once

#include <string>
#include <vector>

#include "problems/dlp/case.hpp"

namespace dlpverify {

struct AuditThresholds {
  double residual = 1e-8;
  double cvode_distance = 1e-9;
};

struct BaselineAudit {
  std::string baseline;  // the case's name, or the published formula's
  bool published = false;   // one of the seed's formulas (expected to fail)
  std::string source;       // "SPEC 4.3 …" or "seed eq. 23 …"
  int particles = 0;
  std::vector<double> times;  // τ audited
  double residual = 0.0;        // largest finite relative ODE residual
  double cvode_distance = 0.0;  // largest finite relative L2 distance from CVODE
  int non_finite = 0;           // residuals or distances that were NaN or infinite (a failure)
  bool passed = false;
};

// Audits the closed form of `test_case` under `physics` up to τ = t_end, on a small sample cloud
// of the case's own shape (a sphere of R_out 4 including the particle at rest at the centre, or
// the seed's z axis for the vertical case). Throws InputError if the case has no closed form.
BaselineAudit audit_case(const Case& test_case, const Physics& physics, double t_end,
                         const AuditThresholds& thresholds = {});

// Every closed form of the registry with default parameters, then the seed's published formulas.
std::vector<BaselineAudit> audit_all(const AuditThresholds& thresholds = {});

}  // namespace dlpverify
