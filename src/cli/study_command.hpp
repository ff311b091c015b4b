// `dlpverify converge` and `dlpverify check`: options → case → integrator → study → reports.
#pragma once

#include <string>

#include "cli/options.hpp"

namespace dlpverify::cli {

// The subcommands, their options bound.
CLI::App* add_converge_command(CLI::App& app, ConvergeOptions& options);
CLI::App* add_check_command(CLI::App& app, CheckOptions& options);

// Runs the study the options describe, prints its table, writes the requested files.
// Returns the exit code: 0 done (or check passed), 1 check failed, 128 + N when signal N stopped
// a journaled study between levels (study/journal.hpp). Throws InputError for bad input —
// before any output exists — and SolverError when a solver fails; check writes its --junit and
// --summary naming such a failure (exit 3) first (case_study::write_failure_reports).
int run_converge_command(ConvergeOptions options, const std::string& command_line);
int run_check_command(CheckOptions options, const std::string& command_line);

}  // namespace dlpverify::cli
