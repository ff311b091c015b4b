// `dlpverify audit`: every closed form proves itself (docs/model.md §4), beside the seed's formulas.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace dlpverify::cli {

struct AuditOptions {
  std::string json_file;
};

// The subcommand, its options bound.
CLI::App* add_audit_command(CLI::App& app, AuditOptions& options);

// Prints the audit table; writes JSON when options.json_file is not empty. Returns 0 when every closed
// form passes, 1 otherwise (the published formulas are expected to fail and do not count).
int run_audit_command(const AuditOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
