// The verdict on the audit of every baseline (`dlpverify audit`, docs/model.md §9): each closed
// form must pass the ODE-residual and CVODE-distance limits; the source paper's published formulas
// are expected to fail and are reported, not judged.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "references/closed_form_audit.hpp"

namespace dlpverify {

struct AuditVerdict {
  bool passed = false;    // every closed form passed
  std::string table;      // a row per baseline, the limits and the verdict
  nlohmann::json report;  // {"baselines": [...], "residual_limit", "cvode_distance_limit", "passed"}
};

AuditVerdict judge_audits(const std::vector<BaselineAudit>& audits, const AuditThresholds& thresholds);

}  // namespace dlpverify
