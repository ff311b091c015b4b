// `dlpverify suite FILE…`: many checks in one command. Each FILE is a study file of `check`
// (--config FILE), run in turn; a study that fails or cannot run never stops the others. Prints one
// summary (study, variable, expected, fitted with its interval, verdict, reason) and a line on
// stderr per finished study; --junit writes every verdict as JUnit XML. Exit 0 when every study
// passes, else the code of case_study::suite_exit_code.
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
};

// The `suite` subcommand of `app`, bound to `options`.
CLI::App* add_suite_command(CLI::App& app, SuiteOptions& options);
int run_suite_command(const SuiteOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
