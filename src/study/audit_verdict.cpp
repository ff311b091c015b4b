#include "study/audit_verdict.hpp"

#include "io/format.hpp"

namespace dlpverify {

namespace {

std::string row_verdict(const BaselineAudit& a) {
  if (a.published) return a.passed ? "PASSES (unexpected for a published error)" : "fails, as docs/model.md §9 says";
  return a.passed ? "pass" : "FAIL";
}

}  // namespace

AuditVerdict judge_audits(const std::vector<BaselineAudit>& audits, const AuditThresholds& thresholds) {
  AuditVerdict verdict;
  verdict.passed = true;
  nlohmann::json rows = nlohmann::json::array();
  std::string& table = verdict.table;
  table = printf_string("%-22s %-10s %9s %13s %15s  %s\n", "baseline", "kind", "particles", "max residual",
                        "CVODE distance", "verdict");
  for (const BaselineAudit& a : audits) {
    if (!a.published) verdict.passed = verdict.passed && a.passed;
    table += printf_string("%-22s %-10s %9d %13.2e %15.2e  %s", a.baseline.c_str(), a.published ? "published" : "closed form",
                           a.particles, a.residual, a.cvode_distance, row_verdict(a).c_str());
    if (a.non_finite > 0) table += printf_string(" (%d non-finite values)", a.non_finite);
    table += "\n";
    rows.push_back({{"baseline", a.baseline},
                    {"published", a.published},
                    {"source", a.source},
                    {"particles", a.particles},
                    {"times", a.times},
                    {"max_residual", a.residual},
                    {"max_cvode_distance", a.cvode_distance},
                    {"non_finite", a.non_finite},
                    {"passed", a.passed}});
  }
  table += printf_string("\nlimits: ODE residual <= %.0e relative (8th-order central difference), CVODE distance <= "
                         "%.0e relative L2 (Adams, rtol 1e-12), at tau = t_end/4, t_end/2, t_end\n%s\n",
                         thresholds.residual, thresholds.cvode_distance,
                         verdict.passed ? "every closed form passed" : "A CLOSED FORM FAILED");
  verdict.report = {{"baselines", rows},
                    {"residual_limit", thresholds.residual},
                    {"cvode_distance_limit", thresholds.cvode_distance},
                    {"passed", verdict.passed}};
  return verdict;
}

}  // namespace dlpverify
