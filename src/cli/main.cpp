// The dlpverify command: the one error boundary. Every failure becomes one line on stderr and a
// documented exit code: 0 done, 1 a check failed, 2 bad input, 3 a solver failed, 4 an output
// could not be written (docs/verification.md, "Exit codes").
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/audit_command.hpp"
#include "cli/command_line.hpp"
#include "cli/compress_command.hpp"
#include "cli/plot_command.hpp"
#include "cli/problems.hpp"
#include "cli/precision_command.hpp"
#include "cli/study_command.hpp"
#include "integrators/registry.hpp"
#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/printable.hpp"
#include "io/progress.hpp"

namespace {

using namespace dlpverify;

void print_cases() {
  std::printf("%-13s %-9s %s\n", "case", "reference", "terms on");
  for (const cli::CaseEntry& c : cli::all_cases()) {
    std::printf("%-13s %-9s %s\n", c.name.c_str(), c.closed_form ? "exact" : "cvode", c.terms.c_str());
    std::printf("%-23s %s\n", "", c.summary.c_str());
    std::printf("%-23s %s\n", "", c.reference_detail.c_str());
    std::printf("%-23s defaults: t-end %g s, dt %g s, %d levels\n", "", c.defaults.t_end, c.defaults.dt, c.defaults.levels);
  }
  std::printf("\n%-43s %5s  %s\n", "integrator", "order", "what");
  for (const auto& i : cli::known_study_integrators())
    std::printf("%-43s %5s  %s\n", i.name.c_str(), i.order > 0 ? std::to_string(i.order).c_str() : "var", i.summary.c_str());
}

std::string join(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i ? " " : "") + std::string(argv[i]);
  return line;
}

int run(int argc, char** argv) {
  cli::CommandLine line;
  try {
    line.parse(line.with_study_file({argv + 1, argv + argc}));
  } catch (const CLI::ParseError& e) {
    return line.app.exit(e);  // --help, --version (parse() turns every other ParseError into InputError)
  }

  const std::string command_line = join(argc, argv);
  // The progress line of long work (io/progress.hpp): on a terminal, for the commands that have --quiet.
  const bool long_work = line.converge->parsed() || line.check->parsed() || line.precision->parsed() ||
                         line.compress->parsed();
  progress::enable(long_work && !line.quiet && progress::stderr_is_terminal());
  if (line.converge->parsed()) return cli::run_converge_command(line.converge_options, command_line);
  if (line.check->parsed()) return cli::run_check_command(line.check_options, command_line);
  if (line.precision->parsed()) return cli::run_precision_command(line.precision_options, command_line);
  if (line.audit->parsed()) return cli::run_audit_command(line.audit_json, command_line);
  if (line.plot->parsed()) return cli::run_plot_command(line.plot_command);
  if (line.bench->parsed()) return cli::run_bench_command(line.bench_options, command_line);
  if (line.stagger->parsed()) return cli::run_stagger_command(line.stagger_options, command_line);
  if (line.compress->parsed()) return cli::run_compress_command(line.compress_options, command_line);
  if (line.tableau->parsed()) return cli::run_tableau_command(line.tableau_options, command_line);
  if (line.compare->parsed()) return cli::run_compare_command(line.compare_options);
  if (line.sharpness->parsed()) return cli::run_sharpness_command(line.sharpness_options, command_line);
  if (line.analyze->parsed()) return cli::run_analyze_command(line.analyze_options, command_line);
  print_cases();
  return kExitDone;
}

}  // namespace

// The library names quantities; the command names the option that set each one. The value is
// the user's text: shown printable and cut (io/printable.hpp).
std::string input_error_line(const InputError& e) {
  static const std::pair<const char*, const char*> options[] = {
      {"time step", "--dt"},           {"step ratio", "--ratio"},          {"duration", "--t-end"},
      {"case", "--case"},              {"integrator", "--integrator"},     {"reference", "--reference"},
      {"relative tolerance", "--rtol"}, {"absolute tolerance", "--atol"},  {"CVODE step limit", "--max-steps"},
      {"reference pressure P0", "--p-ref"},     {"reference temperature T0", "--t-ref"},
      {"molar mass M_g", "--molar-mass"},      {"reference density rho0", "--rho0"},
      {"ratio of specific heats gamma", "--gamma"}, {"van der Waals a", "--vdw-a"},
      {"van der Waals b", "--vdw-b"},          {"van der Waals constants a, b", "--vdw-a, --vdw-b"},
      {"parcels", "--parcels"},                {"path period", "--period"},
      {"deepest compression J_min, low end", "--j-min-low"}, {"deepest compression J_min, high end", "--j-min-high"},
      {"initial temperature spread", "--t-spread"}};
  if (e.quantity().empty()) return e.what();
  std::string option = e.quantity();
  for (const auto& [quantity, name] : options)
    if (e.quantity() == quantity) option = name;
  return option + " = " + printable(e.value()) + ": " + e.reason();
}

// Every error line may carry user text (a path, a parser's quote of a study file): no control
// byte reaches the terminal, and no line runs past a few screen lines.
void report(const std::string& line) { std::cerr << "dlpverify: " << printable(line, 400) << "\n"; }

int main(int argc, char** argv) {
  report_file_size_limit_as_error();
  try {
    return run(argc, argv);
  } catch (const InputError& e) {
    report(input_error_line(e));
    return kExitBadInput;
  } catch (const OutputError& e) {
    report(e.what());
    return kExitOutputFailed;
  } catch (const SolverError& e) {
    report(e.what());
    return kExitSolverFailed;
  } catch (const std::bad_alloc&) {
    std::cerr << "dlpverify: out of memory (try a smaller --outer or --parcels)\n";
    return kExitSolverFailed;
  } catch (const std::exception& e) {
    report(e.what());
    return kExitSolverFailed;
  }
}
