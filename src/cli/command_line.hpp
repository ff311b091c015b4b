// The dlpverify command line as a function of its words: every subcommand with its options, parsed
// into the option structs without running anything (main.cpp runs what was parsed; the fuzz
// targets in tests/fuzz parse only).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/analyze_command.hpp"
#include "cli/audit_command.hpp"
#include "cli/bench_command.hpp"
#include "cli/compare_command.hpp"
#include "cli/compress_command.hpp"
#include "cli/options.hpp"
#include "cli/precision_command.hpp"
#include "cli/plot_command.hpp"
#include "cli/sharpness_command.hpp"
#include "cli/stagger_command.hpp"
#include "cli/study_command.hpp"
#include "cli/suite_command.hpp"
#include "cli/tableau_command.hpp"

namespace dlpverify::cli {

// Not copyable or movable: the options are bound to `app` by reference.
struct CommandLine {
  CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  // The subcommand that reads a study file (converge, check, precision); nullptr for any other word.
  CLI::App* study_subcommand(const std::string& name) const;
  // args: the words after the program's name. A study file given to a study subcommand (--config)
  // is read and its keys put ahead of the typed options (study_file.hpp).
  std::vector<std::string> with_study_file(const std::vector<std::string>& args) const;
  // Parses args (a study file already expanded). Throws InputError for bad input, an empty
  // value and an option that does nothing (idle_options.hpp); lets a CLI::ParseError with exit
  // code 0 (--help, --version) through for app.exit() to print.
  void parse(const std::vector<std::string>& args);

  CLI::App app{"dlpverify: convergence verification of particle ODE integrators (DLP model)"};
  ConvergeOptions converge_options;
  CheckOptions check_options;
  PrecisionOptions precision_options;
  AuditOptions audit_options;
  BenchOptions bench_options;
  PlotCommand plot_command;
  StaggerOptions stagger_options;
  CompressOptions compress_options;
  TableauOptions tableau_options;
  CompareOptions compare_options;
  SharpnessOptions sharpness_options;
  AnalyzeOptions analyze_options;
  SuiteOptions suite_options;
  bool quiet = false;  // --quiet: no progress line (io/progress.hpp)
  CLI::App *converge, *check, *precision, *cases, *audit, *bench, *plot;
  CLI::App *stagger, *compress, *tableau, *compare, *sharpness, *analyze, *suite;
};

}  // namespace dlpverify::cli
