#include "cli/compare_command.hpp"

#include <cmath>
#include <cstdio>

#include "cli/option_checks.hpp"
#include "dlpverify/errors.hpp"
#include "harness/comparison.hpp"
#include "harness/recorded_study.hpp"
#include "io/format.hpp"

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
  return command;
}

int run_compare_command(const CompareOptions& options) {
  require_positive("--order-tolerance", options.order_tolerance);
  require_fraction("--constant-tolerance", options.constant_tolerance);
  const RecordedStudy a = read_recorded_study_file(options.a, "input");
  const RecordedStudy b = read_recorded_study_file(options.b, "input");
  const StudyComparison comparison =
      compare_studies(a, b, ComparisonTolerances{options.order_tolerance, options.constant_tolerance});
  std::fputs(format_comparison(a, b, comparison).c_str(), stdout);
  std::fflush(stdout);
  return comparison.agree ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
