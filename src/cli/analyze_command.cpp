#include "cli/analyze_command.hpp"
#include "cli/failure.hpp"
#include "io/printable.hpp"

#include <iostream>

namespace dlpverify::cli {

CLI::App* add_analyze_command(CLI::App& app, AnalyzeOptions& o) {
  CLI::App* analyze = app.add_subcommand(
      "analyze", "The study of runs your program made itself, one file per dt (exchange HDF5 or CSV): norms, orders, "
                 "reports and figure as converge; check's verdict with --expect-order (" + verdict_exit_codes() + ")");
  analyze->add_option("runs", o.runs, "Run files, one per dt (HDF5 of the exchange format, or CSV)")
      ->required()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  const std::string runs = "Runs (docs/analyze.md)";
  analyze->add_option("--reference", o.reference,
                      "A reference state in the same format [default: none, each run against the next finer]")
      ->group(runs);
  analyze->add_option("--reference-check", o.reference_check,
                      "The reference's program at half its step: estimates the reference's error for the trust rule")
      ->group(runs);
  analyze->add_option("--dt", o.dt, "CSV runs: their steps DT_1,DT_2,... in the order of the runs [s]")
      ->delimiter(',')
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->allow_extra_args(false)  // one value per --dt: the run files after it stay positionals
      ->group(runs);
  analyze->add_option("--t-end", o.t_end, "CSV runs: the duration they cover [s]")->group(runs);
  analyze->add_option("--variable", o.variables, "A measured variable NAME=FIELD,FIELD,... (repeat for more) [default: each field]")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->allow_extra_args(false)  // one NAME=FIELDS per --variable: the run files after it stay positionals
      ->group(runs);
  analyze->add_option("--variables", o.variables_file, "The measured variables from a TOML file of [[variable]] tables")
      ->group(runs);
  analyze->add_option("--order", o.order, "The nominal order of your program (0: not declared)")
      ->capture_default_str()
      ->group(runs);
  analyze->add_option("--label", o.label, "The runs' name in the reports, in the integrator's place")
      ->capture_default_str()
      ->group(runs);
  add_expect_order(*analyze, o.expect_order, o.expect_order_by_variable,
                   "Check: expected order of accuracy P (exit 1 when missed); NAME=P, repeated, for a variable of "
                   "another order");
  analyze->add_option("--order-tolerance", o.order_tolerance, "Pass when |fitted order − P| ≤ this")
      ->capture_default_str()
      ->group("Check");
  add_outputs(*analyze, o.outputs, "study", "Draw error against dt with fitted and reference slopes (.png, .svg or .pdf)");
  analyze->add_flag("--plot-relative", o.plot_relative, "Plot relative L2 errors on one axis")
      ->group("Outputs (written whole at the end, or not at all)");
  analyze->add_option("--junit", o.junit_file,
                      "With --expect-order: write each variable's verdict as JUnit XML (- for standard output)")
      ->group("Outputs (written whole at the end, or not at all)");
  analyze->add_option("--html", o.html_file,
                      "With --expect-order: write the study as one self-contained HTML page")
      ->group("Outputs (written whole at the end, or not at all)");
  return analyze;
}

int run_analyze_command(const AnalyzeOptions& options, const std::string& command_line) {
  const CaseOutcome outcome = case_study::run_analysis(options, command_line);
  std::cout << console_text(outcome.console) << std::flush;
  return outcome.exit_code;
}

}  // namespace dlpverify::cli
