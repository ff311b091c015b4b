// The dlpverify command: the one error boundary. Every failure becomes one line on stderr and a
// documented exit code: 0 done, 1 a check failed, 2 bad input, 3 a solver failed, 4 an output
// could not be written (docs/verification.md, "Exit codes").
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/audit_command.hpp"
#include "cli/options.hpp"
#include "cli/plot_command.hpp"
#include "cli/problems.hpp"
#include "cli/precision_command.hpp"
#include "cli/study_command.hpp"
#include "cli/study_file.hpp"
#include "sundials/integrators.hpp"
#include "dlpverify/errors.hpp"
#include "io/provenance.hpp"

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

// What --help of a study command ends with: every case and every integrator it accepts.
std::string catalogue() {
  std::string text = "Cases (--case):\n";
  for (const cli::CaseEntry& c : cli::all_cases())
    text += "  " + c.name + std::string(c.name.size() < 22 ? 22 - c.name.size() : 1, ' ') + c.summary + "\n";
  text += "Integrators (--integrator):\n";
  for (const auto& i : cli::known_study_integrators())
    text += "  " + i.name + std::string(i.name.size() < 40 ? 40 - i.name.size() : 1, ' ') +
            (i.order > 0 ? "order " + std::to_string(i.order) : std::string("variable order")) + "\n";
  return text;
}

std::string join(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i ? " " : "") + std::string(argv[i]);
  return line;
}

int run(int argc, char** argv) {
  CLI::App app{"dlpverify: convergence verification of particle ODE integrators (DLP model)"};
  app.set_version_flag("--version", version_line());
  // Options take their last value, so a typed option overrides the study file's (study_file.hpp).
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.require_subcommand(1);

  cli::ConvergeOptions converge_options;
  cli::CheckOptions check_options;
  cli::PrecisionOptions precision_options;
  CLI::App* converge = app.add_subcommand("converge", "Run a convergence study: errors and observed orders per level");
  cli::add_options(*converge, converge_options);
  CLI::App* check = app.add_subcommand("check", "A study plus a verdict on its order (exit 0 pass, 1 fail)");
  cli::add_options(*check, check_options);
  CLI::App* precision = app.add_subcommand(
      "precision", "Work-precision study: CVODE Adams and BDF over a tolerance sweep beside a fixed-step method");
  cli::add_options(*precision, precision_options);
  for (CLI::App* study : {converge, check, precision}) study->footer(catalogue());
  app.add_subcommand("cases", "List the verification cases and integrators");
  std::string audit_json;
  CLI::App* audit = app.add_subcommand(
      "audit", "Check every closed form against its ODE and CVODE, beside the seed's published formulas (exit 1 on a failure)");
  audit->add_option("--json", audit_json, "Write the audit as JSON");
  cli::PlotCommand plot_command;
  CLI::App* plot = app.add_subcommand(
      "plot", "Redraw a figure from results alone: converge/check JSON (several: overlay), precision JSON, "
              "--per-particle or --history CSV");
  plot->add_option("inputs", plot_command.inputs, "Result files, all of one kind")
      ->required()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  plot->add_option("-o,--output", plot_command.output, "The figure: .png, .svg or .pdf")->required();
  plot->add_option("--title", plot_command.title, "The figure's title [default: built from the results]");
  plot->add_flag("--relative", plot_command.relative, "Error against dt: relative L2 norms on one axis");
  plot->add_option("--labels", plot_command.labels, "Legend names of the CSV inputs, in order")
      ->delimiter(',')
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);

  // Expand a study file given to a subcommand into options ahead of the typed ones.
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty()) {
    CLI::App* sub = args[0] == "converge"    ? converge
                    : args[0] == "check"     ? check
                    : args[0] == "precision" ? precision
                                             : nullptr;
    if (sub) {
      std::vector<std::string> rest = cli::expand_study_file(*sub, {args.begin() + 1, args.end()});
      rest.insert(rest.begin(), args[0]);
      args = rest;
    }
  }
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    throw InputError(e.what());
  }

  const std::string command_line = join(argc, argv);
  if (converge->parsed()) return cli::run_converge_command(converge_options, command_line);
  if (check->parsed()) return cli::run_check_command(check_options, command_line);
  if (precision->parsed()) return cli::run_precision_command(precision_options, command_line);
  if (audit->parsed()) return cli::run_audit_command(audit_json, command_line);
  if (plot->parsed()) return cli::run_plot_command(plot_command);
  print_cases();
  return kExitDone;
}

}  // namespace

// The library names quantities; the command names the option that set each one.
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
  for (const auto& [quantity, option] : options)
    if (e.quantity() == quantity) return std::string(option) + " = " + e.value() + ": " + e.reason();
  return e.what();
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const InputError& e) {
    std::cerr << "dlpverify: " << input_error_line(e) << "\n";
    return kExitBadInput;
  } catch (const OutputError& e) {
    std::cerr << "dlpverify: " << e.what() << "\n";
    return kExitOutputFailed;
  } catch (const SolverError& e) {
    std::cerr << "dlpverify: " << e.what() << "\n";
    return kExitSolverFailed;
  } catch (const std::bad_alloc&) {
    std::cerr << "dlpverify: out of memory (try a smaller --outer)\n";
    return kExitSolverFailed;
  } catch (const std::exception& e) {
    std::cerr << "dlpverify: " << e.what() << "\n";
    return kExitSolverFailed;
  }
}
