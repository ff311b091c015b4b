// `dlpverify compare A.json B.json`: two results of the same study, level by level, and a verdict
// (harness/comparison.hpp), on the console and with --json as JSON. Exit 0 they agree, 1 they
// differ, 2 they are not of one study.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "harness/constant_gate.hpp"

namespace dlpverify::cli {

struct CompareOptions {
  std::string a, b;  // converge or check JSON results
  double order_tolerance = 0.1;
  double constant_tolerance = kDefaultConstantTolerance;
  std::string json_file;  // --json: the comparison as JSON, written whole or not at all
};

// The `compare` subcommand of `app`, bound to `options`.
CLI::App* add_compare_command(CLI::App& app, CompareOptions& options);
int run_compare_command(const CompareOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
