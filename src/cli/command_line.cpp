#include "cli/command_line.hpp"

#include "cli/idle_options.hpp"
#include "cli/problems.hpp"
#include "cli/study_file.hpp"
#include "dlpverify/errors.hpp"
#include "io/provenance.hpp"
#include "integrators/registry.hpp"

namespace dlpverify::cli {

namespace {

// What --help of a study command ends with: every case and every integrator it accepts.
std::string catalogue() {
  std::string text = "Cases (--case):\n";
  for (const CaseEntry& c : all_cases())
    text += "  " + c.name + std::string(c.name.size() < 22 ? 22 - c.name.size() : 1, ' ') + c.summary + "\n";
  text += "Integrators (--integrator):\n";
  for (const auto& i : known_study_integrators())
    text += "  " + i.name + std::string(i.name.size() < 40 ? 40 - i.name.size() : 1, ' ') +
            (i.order > 0 ? "order " + std::to_string(i.order) : std::string("variable order")) + "\n";
  text += "Adaptive integrators (--integrator with --tolerances; also exec:COMMAND with {rtol}):\n";
  for (const auto& i : adaptive_integrators())
    text += "  " + i.name + std::string(i.name.size() < 47 ? 47 - i.name.size() : 1, ' ') +
            (i.order > 0 ? "order " + std::to_string(i.order) : std::string("variable order")) + "\n";
  return text;
}

const char* const kEmptyValue = "is empty; give a value, or leave the option out for its default";

// An empty value is refused, never taken as "not given": CLI11 converts "" to 0 or keeps the
// default, so `--json ''` would write nothing and `--baseline ''` turn its gate off. Every option
// that takes a value (flags take none) of every command checks each value it is given.
void refuse_empty_values(CLI::App& command) {
  for (CLI::Option* option : command.get_options()) {
    if (option->get_expected_max() == 0) continue;
    const std::string name = option->get_name();
    option->check(CLI::Validator(
        [name](std::string& value) -> std::string {
          if (value.empty()) throw InputError(name, "''", kEmptyValue);
          return {};
        },
        ""));
  }
  for (CLI::App* sub : command.get_subcommands({})) refuse_empty_values(*sub);
}

// `--json=` holds no value: CLI11 would take the next word as its value, or none.
void refuse_empty_equals(const std::vector<std::string>& args) {
  for (const std::string& word : args) {
    if (word == "--") return;  // the rest are positional
    if (word.size() > 3 && word.rfind("--", 0) == 0 && word.find('=') == word.size() - 1)
      throw InputError(word.substr(0, word.size() - 1), "''", kEmptyValue);
  }
}

}  // namespace

CommandLine::CommandLine() {
  app.name("dlpverify");  // the usage line names the program: Usage: dlpverify [OPTIONS] SUBCOMMAND
  app.set_version_flag("--version", version_line());
  // Options take their last value, so a typed option overrides the study file's (study_file.hpp).
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.require_subcommand(1);

  // Every command the same way: its file's add_NAME_command binds its options (main.cpp runs it).
  converge = add_converge_command(app, converge_options);
  check = add_check_command(app, check_options);
  precision = add_precision_command(app, precision_options);
  for (CLI::App* study : {converge, check, precision}) study->footer(catalogue());
  cases = app.add_subcommand("cases", "List the verification cases and integrators");
  audit = add_audit_command(app, audit_options);
  bench = add_bench_command(app, bench_options);
  stagger = add_stagger_command(app, stagger_options);
  plot = add_plot_command(app, plot_command);
  compress = add_compress_command(app, compress_options);
  tableau = add_tableau_command(app, tableau_options);
  compare = add_compare_command(app, compare_options);
  sharpness = add_sharpness_command(app, sharpness_options);
  sharpness->footer(catalogue());
  analyze = add_analyze_command(app, analyze_options);
  suite = add_suite_command(app, suite_options);
  // Not an option of the computation: it changes no result, so it is in no result file either.
  for (CLI::App* long_work : {converge, check, precision, compress})
    long_work->add_flag("--quiet", quiet, "No progress on stderr (shown on a terminal, and in a CI's log: CI set)");
  refuse_empty_values(app);
}

CLI::App* CommandLine::study_subcommand(const std::string& name) const {
  return name == "converge" ? converge : name == "check" ? check : name == "precision" ? precision : nullptr;
}

std::vector<std::string> CommandLine::with_study_file(const std::vector<std::string>& args) const {
  CLI::App* sub = args.empty() ? nullptr : study_subcommand(args[0]);
  if (!sub) return args;
  std::vector<std::string> expanded = expand_study_file(*sub, {args.begin() + 1, args.end()});
  expanded.insert(expanded.begin(), args[0]);
  return expanded;
}

void CommandLine::parse(const std::vector<std::string>& args) {
  refuse_empty_equals(args);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) throw;  // --help, --version
    throw InputError(e.what());
  }
  refuse_idle_options(*this);
}

}  // namespace dlpverify::cli
