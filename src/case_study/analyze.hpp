// `dlpverify analyze RUN… [--reference REF]`: the study of runs a user's program made itself, one
// file per Δt (docs/analyze.md), as the case "analyze": the same levels, norms, orders, reports
// and figure as converge, and check's verdict (study/verdict.hpp) and exit code with --expect-order.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "case_study/options.hpp"
#include "case_study/outcome.hpp"

namespace dlpverify::case_study {

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
  std::map<std::string, double> expect_order_by_variable;  // --expect-order NAME=P: a variable's own
  double order_tolerance = 0.1;
  std::string label = "runs";           // the runs' name in reports (the integrator's place)
  OutputOptions outputs;
  bool plot_relative = false;
  std::string junit_file;  // --junit: the verdicts as JUnit XML (with --expect-order)
  std::string html_file;   // --html: the study as a self-contained page (with --expect-order)
};

// The study of the runs `options` name, its files written together (io/atomic_file.hpp) and the
// console table left to the caller. Exit code 0 done (or the check passed), 1 the check failed;
// InputError for bad input or runs that do not belong together, before any output exists.
CaseOutcome run_analysis(const AnalyzeOptions& options, const std::string& command_line);

}  // namespace dlpverify::case_study
