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

namespace dlpverify::cli {

struct SuiteOptions {
  std::vector<std::string> files;  // the study files, run in this order
  std::string junit_file;          // --junit: the verdicts as JUnit XML
  std::string table_file;          // --table: the summary to a file too
  std::string html_file;           // --html: the suite as one self-contained HTML page
  std::string json_file;           // --json: every study's verdicts and result; the journal beside it
  int jobs = 1;                    // --jobs: studies at once
  int threads = 0;                 // --threads: OpenMP threads for them all
  bool resume = false, restart = false;  // --resume, --restart: the journal beside --json
};

// The `suite` subcommand of `app`, bound to `options`.
CLI::App* add_suite_command(CLI::App& app, SuiteOptions& options);
int run_suite_command(const SuiteOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
