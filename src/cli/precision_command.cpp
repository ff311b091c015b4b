#include "cli/precision_command.hpp"

#include <iostream>

#include "case_study/precision.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

CLI::App* add_precision_command(CLI::App& app, PrecisionOptions& options) {
  CLI::App* precision = app.add_subcommand(
      "precision", "Work-precision study: CVODE Adams and BDF over a tolerance sweep beside a fixed-step method");
  add_options(*precision, options);
  return precision;
}

int run_precision_command(PrecisionOptions options, const std::string& command_line) {
  const CaseOutcome outcome = case_study::run_precision(options, command_line);
  std::cout << console_text(outcome.console) << std::flush;
  return outcome.exit_code;
}

}  // namespace dlpverify::cli
