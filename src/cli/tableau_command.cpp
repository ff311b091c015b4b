#include "cli/tableau_command.hpp"

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"
#include "integrators/tableau/tableau_file.hpp"
#include "integrators/tableau/tableau_report.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/output_path.hpp"
#include "io/provenance.hpp"
#include "io/file_identity.hpp"

namespace dlpverify::cli {

CLI::App* add_tableau_command(CLI::App& app, TableauOptions& options) {
  CLI::App* command = app.add_subcommand(
      "tableau", "Check a Butcher tableau file (TOML) against its row sums and order conditions up to order 6 "
                 "(exit 0 its claimed order is met, 1 not)");
  command->add_option("file", options.file, "The tableau: name, order, c, b, A [, b_embedded, embedded_order]")->required();
  command->add_option("--json", options.json_file, "Write every condition and the verdict as JSON");
  return command;
}

int run_tableau_command(const TableauOptions& options, const std::string& command_line) {
  refuse_shared_files({{"tableau file", options.file}}, {{"--json", options.json_file}});
  if (!options.json_file.empty()) check_output_path("--json", options.json_file);
  const bool json_on_stdout = !options.json_file.empty() && output_target(options.json_file) == OutputTarget::standard_output;
  const RuntimeTableau tableau = read_tableau_file(options.file);
  const TableauVerdict verdict = judge_tableau(tableau);
  if (!options.json_file.empty()) {
    nlohmann::json j = verdict.report;
    j["provenance"] = provenance(command_line);
    write_output(options.json_file, json_text(j, 2) + "\n");
  }
  if (!json_on_stdout) std::fputs(verdict.table.c_str(), stdout);  // after the output: nothing printed if it fails
  std::fflush(stdout);
  return verdict.passed ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
