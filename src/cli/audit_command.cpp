#include "cli/audit_command.hpp"

#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/problems.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"

namespace dlpverify::cli {

int run_audit_command(const std::string& json_file, const std::string& command_line) {
  if (!json_file.empty()) check_output_path("--json", json_file);
  const bool json_on_stdout = !json_file.empty() && output_target(json_file) == OutputTarget::standard_output;
  const AuditThresholds thresholds;
  const std::vector<BaselineAudit> audits = audit_all();

  bool every_closed_form_passed = true;
  nlohmann::json rows = nlohmann::json::array();
  std::string table = printf_string("%-22s %-10s %9s %13s %15s  %s\n", "baseline", "kind", "particles",
                                    "max residual", "CVODE distance", "verdict");
  for (const BaselineAudit& a : audits) {
    std::string verdict;
    if (a.published)
      verdict = a.passed ? "PASSES (unexpected for a published error)" : "fails, as docs/model.md §9 says";
    else
      verdict = a.passed ? "pass" : "FAIL";
    if (!a.published) every_closed_form_passed = every_closed_form_passed && a.passed;
    table += printf_string("%-22s %-10s %9d %13.2e %15.2e  %s", a.baseline.c_str(),
                           a.published ? "published" : "closed form", a.particles, a.residual, a.cvode_distance,
                           verdict.c_str());
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
                         every_closed_form_passed ? "every closed form passed" : "A CLOSED FORM FAILED");
  if (!json_file.empty()) {
    const nlohmann::json j{{"baselines", rows},
                           {"residual_limit", thresholds.residual},
                           {"cvode_distance_limit", thresholds.cvode_distance},
                           {"passed", every_closed_form_passed},
                           {"provenance", provenance(command_line)}};
    write_output(json_file, json_text(j, 2) + "\n");
  }
  if (!json_on_stdout) std::fputs(table.c_str(), stdout);  // after the output: nothing printed if it fails
  std::fflush(stdout);
  return every_closed_form_passed ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
