#include "cli/audit_command.hpp"

#include <cstdio>

#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "study/audit_verdict.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

CLI::App* add_audit_command(CLI::App& app, AuditOptions& options) {
  CLI::App* audit = app.add_subcommand(
      "audit", "Check every closed form against its ODE and CVODE, beside Kuhl & Grote's published formulas (exit 1 on a failure)");
  audit->add_option("--json", options.json_file, "Write the audit as JSON");
  return audit;
}

int run_audit_command(const AuditOptions& options, const std::string& command_line) {
  const std::string& json_file = options.json_file;
  if (!json_file.empty()) check_output_path("--json", json_file);
  const bool json_on_stdout = !json_file.empty() && output_target(json_file) == OutputTarget::standard_output;
  const AuditVerdict verdict = judge_audits(audit_all(), AuditThresholds{});
  if (!json_file.empty()) {
    nlohmann::json j = verdict.report;
    j["provenance"] = provenance(command_line);
    write_output(json_file, json_text(j, 2) + "\n");
  }
  if (!json_on_stdout) std::fputs(console_text(verdict.table).c_str(), stdout);  // after the output: nothing printed if it fails
  std::fflush(stdout);
  return verdict.passed ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
