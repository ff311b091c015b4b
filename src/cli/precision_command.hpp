// `dlpverify precision`: a work-precision study. CVODE Adams and BDF over a sweep of relative
// tolerances (atol = rtol × each field's size), and a fixed-step method (rk2 by default) at the
// study levels, each measured against the case's reference: error against RHS evaluations and
// wall time.
#pragma once

#include <string>

#include "cli/options.hpp"

namespace dlpverify::cli {

// The subcommand, its options bound.
CLI::App* add_precision_command(CLI::App& app, PrecisionOptions& options);

// Runs the study the options describe, prints its table, writes the requested files. Returns 0.
// Throws InputError for bad input — before any work or output — and SolverError, naming the case
// and the run, when a solver fails (no file is written then).
int run_precision_command(PrecisionOptions options, const std::string& command_line);

}  // namespace dlpverify::cli
