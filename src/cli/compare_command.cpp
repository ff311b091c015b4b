#include "cli/compare_command.hpp"

#include <cmath>
#include <cstdio>
#include <system_error>

#include "io/value_checks.hpp"
#include "dlpverify/errors.hpp"
#include "harness/comparison.hpp"
#include "dlpverify/recorded_study.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/output_path.hpp"
#include "io/provenance.hpp"
#include "io/file_identity.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

CLI::App* add_compare_command(CLI::App& app, CompareOptions& options) {
  CLI::App* command = app.add_subcommand(
      "compare", "Compare two converge/check JSON results of one study (case, parameters, levels) level by level: "
                 "errors, orders, error constants (exit 0 they agree, 1 they differ)");
  command->add_option("a", options.a, "The first result (A, the baseline)")->required();
  command->add_option("b", options.b, "The second result (B, judged against A)")->required();
  command->add_option("--order-tolerance", options.order_tolerance, "Agree when |fitted order B − A| ≤ this")
      ->capture_default_str();
  command->add_option("--constant-tolerance", options.constant_tolerance, "Agree when |C_B − C_A| ≤ this × C_A")
      ->capture_default_str();
  command->add_option("--json", options.json_file, "Write the comparison as JSON (per variable, level by level)");
  return command;
}

namespace {

// --json may not replace either input (the comparison would destroy what it compared).
void check_json_output(const CompareOptions& options) {
  if (options.json_file.empty() || output_target(options.json_file) != OutputTarget::file) return;
  refuse_shared_files({{"result", options.a}, {"result", options.b}}, {{"--json", options.json_file}});
  check_output_path("--json", options.json_file);
}

}  // namespace

int run_compare_command(const CompareOptions& options, const std::string& command_line) {
  require_positive("--order-tolerance", options.order_tolerance);
  require_fraction("--constant-tolerance", options.constant_tolerance);
  check_json_output(options);
  const RecordedStudy a = read_recorded_study_file(options.a, "input");
  const RecordedStudy b = read_recorded_study_file(options.b, "input");
  const StudyComparison comparison =
      compare_studies(a, b, ComparisonTolerances{options.order_tolerance, options.constant_tolerance});
  const bool json_on_stdout = !options.json_file.empty() && output_target(options.json_file) == OutputTarget::standard_output;
  if (!options.json_file.empty()) {
    nlohmann::json j = comparison_json(a, b, comparison);
    j["provenance"] = provenance(command_line);
    OutputSet outputs;
    outputs.add(options.json_file, json_text(j, 2) + "\n");
    outputs.commit();
  }
  if (!json_on_stdout) std::fputs(console_text(format_comparison(a, b, comparison)).c_str(), stdout);
  std::fflush(stdout);
  return comparison.agree ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
