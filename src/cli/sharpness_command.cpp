#include "cli/sharpness_command.hpp"

#include <iostream>

#include "case_study/sharpness.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

CLI::App* add_sharpness_command(CLI::App& app, SharpnessOptions& options) {
  CLI::App* command = app.add_subcommand(
      "sharpness", "How sharp the check is: perturb each coefficient of a Butcher tableau alone and report which "
                   "check (order conditions, fitted order, error constant) catches each (exit 1: one escapes all)");
  add_options(*command, options);
  return command;
}

int run_sharpness_command(SharpnessOptions options, const std::string& command_line) {
  const CaseOutcome outcome = case_study::run_sharpness(options, command_line);
  std::cout << console_text(outcome.console) << std::flush;
  return outcome.exit_code;
}

}  // namespace dlpverify::cli
