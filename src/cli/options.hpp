// The options of `dlpverify converge`, `check`, `precision` and `sharpness` bound to their
// commands. The options themselves, their defaults, checks and report are the case study's
// (case_study/options.hpp): a command binds only the groups that mean something to it.
#pragma once

#include <CLI/CLI.hpp>

#include "case_study/options.hpp"

namespace dlpverify::cli {

// The command line's options are the case study's request, field for field.
using namespace case_study;

// --json, --csv, --table, --plot and --title of a command whose result is `what` ("study", "runs"),
// with `figure` the help of --plot.
void add_outputs(CLI::App& app, OutputOptions& options, const char* what, const char* figure);

// --expect-order P, and NAME=P repeated for a variable of its own order, into `order` and
// `by_variable` (add_expected_order), with `help`.
void add_expect_order(CLI::App& app, std::optional<double>& order, std::map<std::string, double>& by_variable,
                      const std::string& help);

void add_options(CLI::App& app, ConvergeOptions& options);
void add_options(CLI::App& app, CheckOptions& options);
void add_options(CLI::App& app, PrecisionOptions& options);
void add_options(CLI::App& app, SharpnessOptions& options);

}  // namespace dlpverify::cli
