// `dlpverify analyze RUN… [--reference REF]`: the study of runs a user's program made itself, one
// file per Δt (docs/analyze.md): the same levels, norms, orders, reports and figure as converge,
// and check's verdict and exit code with --expect-order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/options.hpp"

namespace dlpverify::cli {

struct AnalyzeOptions {
  std::vector<std::string> runs;        // the run files, any order (sorted by their steps)
  std::string reference;                // --reference REF; empty: each run against the next finer
  std::string reference_check;          // --reference-check REF2: REF's program at half its step
  std::vector<double> dt;               // --dt, CSV runs' steps in the order of `runs`
  std::optional<double> t_end;          // --t-end, the duration CSV runs cover
  std::vector<std::string> variables;   // --variable NAME=F1,F2,…
  std::string variables_file;           // --variables FILE (TOML)
  int order = 0;                        // --order, the program's nominal order (0: not declared)
  std::optional<double> expect_order;   // --expect-order: check's verdict
  double order_tolerance = 0.1;
  std::string label = "runs";           // the runs' name in reports (the integrator's place)
  OutputOptions outputs;
  bool plot_relative = false;
};

// The `analyze` subcommand of `app`, bound to `options`.
CLI::App* add_analyze_command(CLI::App& app, AnalyzeOptions& options);
// Exit 0 done (or the check passed), 1 the check failed; InputError for bad input or runs that
// do not belong together, before any output exists.
int run_analyze_command(const AnalyzeOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
