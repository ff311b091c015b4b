#include "cli/suite_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "case_study/converge.hpp"
#include "case_study/html_report.hpp"
#include "case_study/inputs.hpp"
#include "case_study/options.hpp"
#include "case_study/setup.hpp"
#include "case_study/suite.hpp"
#include "cli/command_line.hpp"
#include "cli/failure.hpp"
#include "io/atomic_file.hpp"
#include "io/file_identity.hpp"
#include "io/format.hpp"
#include "io/input_file.hpp"
#include "io/output_path.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

namespace {

// One study file through `check`, as `dlpverify check --config FILE` runs it.
case_study::SuiteStudy run_study_file(const std::string& file, const std::string& command_line) {
  case_study::SuiteStudy study;
  study.name = std::filesystem::path(file).stem().string();
  const auto start = std::chrono::steady_clock::now();
  try {
    CommandLine line;
    line.parse(line.with_study_file({"check", "--config", file}));
    study.outcome = case_study::run_case(line.check_options, &line.check_options, command_line + " [" + file + "]");
  } catch (...) {
    const Failure failure = failure_of(std::current_exception());
    study.code = failure.code;
    study.error = failure.line;
  }
  study.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (study.outcome) study.outcome->seconds = study.seconds;
  return study;
}

}  // namespace

CLI::App* add_suite_command(CLI::App& app, SuiteOptions& options) {
  CLI::App* suite = app.add_subcommand("suite", "Run many checks (study files) in one command: one summary, one exit code");
  suite->add_option("files", options.files, "Study files of check (as --config takes them), run in this order")
      ->required()
      ->expected(1, -1);
  suite->add_option("--junit", options.junit_file, "Write every verdict as JUnit XML, the test report CI systems show (- for standard output)");
  suite->add_option("--table", options.table_file, "Write the summary to a file too");
  suite->add_option("--html", options.html_file,
                    "Write the suite as one self-contained HTML page: verdicts, figures, levels, reference, provenance");
  return suite;
}

int run_suite_command(const SuiteOptions& options, const std::string& command_line) {
  // The suite's own input, checked before any study runs: every file readable, every output
  // writable and none on a study file.
  std::vector<NamedPath> inputs;
  for (const std::string& file : options.files) {
    check_input_file("study file", file, input_limit::study_file);
    inputs.push_back({"study file", file});
  }
  const std::vector<std::pair<std::string, std::string>> files{
      {"--junit", options.junit_file}, {"--table", options.table_file}, {"--html", options.html_file}};
  case_study::validate_outputs(files, "");  // two on one path, or on standard output, refused
  case_study::check_outputs(files);
  refuse_shared_files(inputs, case_study::named_paths(files));

  std::vector<case_study::SuiteStudy> studies;
  std::map<std::string, int> named;  // a name given twice (a.toml in two folders) gets " (2)", " (3)", …
  for (std::size_t i = 0; i < options.files.size(); ++i) {
    studies.push_back(run_study_file(options.files[i], command_line));
    case_study::SuiteStudy& study = studies.back();
    if (const int n = ++named[study.name]; n > 1) study.name += " (" + std::to_string(n) + ")";
    if (study.outcome) study.outcome->study = study.name;
    if (study.exit_code() >= kExitStoppedBySignal) return study.exit_code();  // a signal stops the suite too
    std::cerr << printf_string("dlpverify suite: [%zu/%zu] %s: %s (%.2f s)", i + 1, options.files.size(),
                               printable(study.name).c_str(), case_study::study_verdict_word(study.exit_code()).c_str(), study.seconds)
              << (study.error.empty() ? "" : ": " + printable(study.error, 400)) << std::endl;
  }
  const std::string table = case_study::suite_table(studies);
  OutputSet outputs;
  if (!options.junit_file.empty()) outputs.add(options.junit_file, junit_xml(case_study::suite_junit(studies)));
  if (!options.table_file.empty()) outputs.add(options.table_file, table);
  if (!options.html_file.empty()) outputs.add(options.html_file, case_study::html_report("suite of " + std::to_string(studies.size()) + " studies", studies));
  outputs.commit();
  const bool on_stdout = case_study::any_on_standard_output(files);
  if (!on_stdout) std::fputs(table.c_str(), stdout);
  std::fflush(stdout);
  return case_study::suite_exit_code(studies);
}

}  // namespace dlpverify::cli
