// `dlpverify analyze RUN… [--reference REF]`: the study of runs a user's program made itself
// (case_study/analyze.hpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "case_study/analyze.hpp"
#include "cli/options.hpp"

namespace dlpverify::cli {

// The `analyze` subcommand of `app`, bound to `options`.
CLI::App* add_analyze_command(CLI::App& app, AnalyzeOptions& options);
// Exit 0 done (or the check passed), 1 the check failed; InputError for bad input or runs that
// do not belong together, before any output exists.
int run_analyze_command(const AnalyzeOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
