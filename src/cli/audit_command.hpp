// `dlpverify audit`: every closed form proves itself (docs/model.md §4), beside the seed's formulas.
#pragma once

#include <string>

namespace dlpverify::cli {

// Prints the audit table; writes JSON when json_file is not empty. Returns 0 when every closed
// form passes, 1 otherwise (the published formulas are expected to fail and do not count).
int run_audit_command(const std::string& json_file, const std::string& command_line);

}  // namespace dlpverify::cli
