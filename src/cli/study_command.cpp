#include "cli/study_command.hpp"

#include <chrono>
#include <exception>
#include <iostream>

#include "case_study/converge.hpp"
#include "io/printable.hpp"
#include "cli/failure.hpp"

namespace dlpverify::cli {

CLI::App* add_converge_command(CLI::App& app, ConvergeOptions& options) {
  CLI::App* converge = app.add_subcommand("converge", "Run a convergence study: errors and observed orders per level");
  add_options(*converge, options);
  return converge;
}

CLI::App* add_check_command(CLI::App& app, CheckOptions& options) {
  CLI::App* check = app.add_subcommand("check", "A study plus a verdict on its order (" + verdict_exit_codes() + ")");
  add_options(*check, options);
  return check;
}

int run_converge_command(ConvergeOptions options, const std::string& command_line) {
  const CaseOutcome outcome = case_study::run_case(options, nullptr, command_line);
  std::cout << console_text(outcome.console) << std::flush;
  return outcome.exit_code;
}

int run_check_command(CheckOptions options, const std::string& command_line) {
  const auto start = std::chrono::steady_clock::now();
  CaseOutcome outcome;
  try {
    outcome = case_study::run_case(options, &options, command_line);
  } catch (...) {
    // A CI job whose solver or program failed still shows a report naming the failure.
    const Failure failure = failure_of(std::current_exception());
    if (failure.code == kExitSolverFailed) {
      try {
        case_study::write_failure_reports(options, failure.code, failure.line,
                                          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      } catch (...) {
        report(failure_of(std::current_exception()).line);  // the solver's failure stays the outcome
      }
    }
    throw;
  }
  std::cout << console_text(outcome.console) << std::flush;
  return outcome.exit_code;
}

}  // namespace dlpverify::cli
