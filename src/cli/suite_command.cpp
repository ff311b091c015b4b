#include "cli/suite_command.hpp"

#include <chrono>
#include <exception>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "case_study/converge.hpp"
#include "case_study/inputs.hpp"
#include "case_study/options.hpp"
#include "case_study/setup.hpp"
#include "case_study/suite_run.hpp"
#include "cli/command_line.hpp"
#include "cli/failure.hpp"
#include "io/file_identity.hpp"
#include "io/format.hpp"
#include "io/input_file.hpp"
#include "io/output_path.hpp"
#include "io/printable.hpp"
#include "study/journal.hpp"

namespace dlpverify::cli {

namespace {

// A study file's options as `check --config FILE` parses them, or why it does not parse.
struct ParsedStudy { case_study::CheckOptions options; std::exception_ptr failure; };

ParsedStudy parse_study_file(const std::string& file) try {
  CommandLine line;
  line.parse(line.with_study_file({"check", "--config", file}));
  return {line.check_options, nullptr};
} catch (...) {
  return {{}, std::current_exception()};
}

// The line refusing each study that would write a file an earlier study writes, one of the
// suite's own outputs or a study file (a suite writes each file once, and never over what it
// reads); empty for the others, and for a study file that does not parse (running it says why).
std::vector<std::string> shared_file_refusals(const std::vector<NamedPath>& study_files, const std::vector<ParsedStudy>& studies,
                                              const std::vector<NamedPath>& suite_outputs) {
  std::vector<NamedPath> written = suite_outputs;
  std::vector<std::string> refusals(study_files.size());
  for (std::size_t i = 0; i < study_files.size(); ++i) {
    if (studies[i].failure) continue;
    const std::vector<NamedPath> own = case_study::named_paths(case_study::output_files(studies[i].options), true);
    std::vector<NamedPath> outputs = written;
    outputs.insert(outputs.end(), own.begin(), own.end());
    try {
      // The suite's summary and reports own standard output: a study's output there would be mixed into them.
      for (const NamedPath& output : own)
        if (output_target(output.path) == OutputTarget::standard_output)
          throw InputError(output.name, printable(output.path),
                           "a study of a suite writes no output to standard output (the suite's summary and reports "
                           "go there): name a file");
      refuse_shared_files(study_files, outputs);
    } catch (...) {
      refusals[i] = failure_of(std::current_exception()).line;
      continue;
    }
    for (const NamedPath& output : own)
      written.push_back({(output.name.rfind("the ", 0) == 0 ? "" : "the ") + output.name + " of " + study_files[i].path, output.path});
  }
  return refusals;
}

// One study file through `check`, as `dlpverify check --config FILE` runs it. A study whose own
// journal (beside its `json`) is there, kept when a signal stopped the suite, is resumed or
// restarted as the suite is; a level search's journal holds no level, and a plain run starts it over.
case_study::SuiteStudy run_study_file(const std::string& file, const ParsedStudy& parsed, const SuiteOptions& options,
                                      const std::string& command_line) {
  case_study::SuiteStudy study;
  const auto start = std::chrono::steady_clock::now();
  try {
    if (parsed.failure) std::rethrow_exception(parsed.failure);
    case_study::CheckOptions check = parsed.options;
    const std::string own_journal = journal_path(check.outputs.json_file);
    std::error_code ec;
    if (!own_journal.empty() && std::filesystem::exists(own_journal, ec) && !check.levels.auto_levels) {
      check.resume = options.resume;
      check.restart = options.restart;
    }
    study.outcome = case_study::run_case(check, &check, command_line + " [" + file + "]");
  } catch (...) {
    const Failure failure = failure_of(std::current_exception());
    study.code = failure.code;
    study.error = failure.line;
  }
  study.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (study.outcome) study.outcome->seconds = study.seconds;
  return study;
}

// "dlpverify suite: [3/47] drag-rk2: pass (0.04 s)", a line a CI's log shows as it comes.
void say_ended(const case_study::SuiteStudy& study, std::size_t finished, std::size_t total) {
  std::cerr << printf_string("dlpverify suite: [%zu/%zu] %s: %s (%.2f s)", finished, total, printable(study.name).c_str(),
                             case_study::study_verdict_word(study.exit_code()).c_str(), study.seconds)
            << (study.error.empty() ? "" : ": " + printable(study.error, 400)) << std::endl;
}

}  // namespace

CLI::App* add_suite_command(CLI::App& app, SuiteOptions& options) {
  CLI::App* suite = app.add_subcommand("suite", "Run many checks (study files) in one command: one summary, one exit code");
  suite->add_option("files", options.request.files, "Study files of check (as --config takes them), summarised in this order")
      ->required()
      ->expected(1, -1);
  suite->add_option("-j,--jobs", options.request.jobs,
                    "Studies run at once, sharing --threads (0: one a thread); each study file's own threads are kept")
      ->capture_default_str();
  suite->add_option("--threads", options.request.threads, "OpenMP threads for all the studies under way (0: all cores)")
      ->capture_default_str();
  suite->add_option("--junit", options.request.junit_file, "Write every verdict as JUnit XML, the test report CI systems show (- for standard output)");
  suite->add_option("--table", options.request.table_file, "Write the summary to a file too");
  suite->add_option("--summary", options.request.summary_file,
                    "Write one Markdown line per study, failures first, for $GITHUB_STEP_SUMMARY or a merge-request "
                    "comment (- for standard output)");
  suite->add_option("--html", options.request.html_file,
                    "Write the suite as one self-contained HTML page: verdicts, figures, levels, reference, provenance");
  suite->add_option("--json", options.request.json_file,
                    "Write every study's verdicts and JSON result; keeps the journal of finished studies beside it");
  CLI::Option* resuming =
      suite->add_flag("--resume", options.resume,
                      "Continue the suite from its journal beside --json (kept when a signal stopped it): the studies "
                      "it holds are not run again; refused when a study file or the build differs");
  suite->add_flag("--restart", options.restart, "Discard the journal beside --json, if there is one, and run every study")
      ->excludes(resuming);
  return suite;
}

int run_suite_command(const SuiteOptions& options, const std::string& command_line) {
  case_study::SuiteRequest request = options.request;
  request.start = case_study::journal_start(options.resume, options.restart);
  request.command_line = command_line;

  // The suite's own input, checked before any study runs: every file readable, every output
  // writable and none on a study file.
  case_study::validate(request);
  std::vector<NamedPath> inputs;
  for (const std::string& file : request.files) {
    check_input_file("study file", file, input_limit::study_file);
    inputs.push_back({"study file", file});
  }
  const std::vector<std::pair<std::string, std::string>> files{{"--junit", request.junit_file},
                                                               {"--table", request.table_file},
                                                               {"--summary", request.summary_file},
                                                               {"--html", request.html_file},
                                                               {"--json", request.json_file}};
  case_study::validate_outputs(files, "");  // two on one path, or on standard output, refused
  case_study::check_outputs(files);
  refuse_shared_files(inputs, case_study::named_paths(files, true));

  std::vector<ParsedStudy> studies;
  for (const std::string& file : request.files) studies.push_back(parse_study_file(file));
  const std::vector<std::string> refusals = shared_file_refusals(inputs, studies, case_study::named_paths(files, true));
  const auto run = [&](std::size_t i) {
    if (refusals[i].empty()) return run_study_file(request.files[i], studies[i], options, command_line);
    case_study::SuiteStudy refused;
    refused.code = kExitBadInput;
    refused.error = refusals[i];
    return refused;
  };
  const case_study::SuiteOutcome outcome = case_study::run_suite(request, run, say_ended);
  if (!outcome.table.empty() && !case_study::any_on_standard_output(files)) std::fputs(console_text(outcome.table).c_str(), stdout);
  std::fflush(stdout);
  return outcome.exit_code;
}

}  // namespace dlpverify::cli
