// `dlpverify suite FILE…`: many checks in one command. Each FILE is a study file of `check`
// (--config FILE), --jobs of them at once; a study that fails or cannot run never stops the others.
// Prints one summary (study, variable, expected, fitted with its interval, verdict, reason) and a
// line on stderr per finished study; --junit, --html and --json write the verdicts for a CI, and
// the journal beside --json lets an interrupted suite --resume. Exit 0 when every study passes,
// else the code of case_study::suite_exit_code. The running is case_study::run_suite's.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "case_study/suite_run.hpp"

namespace dlpverify::cli {

struct SuiteOptions {
  case_study::SuiteRequest request;      // the files, --jobs, --threads and the outputs, bound as given
  bool resume = false, restart = false;  // --resume, --restart: the journal beside --json
};

// The `suite` subcommand of `app`, bound to `options`.
CLI::App* add_suite_command(CLI::App& app, SuiteOptions& options);
int run_suite_command(const SuiteOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
