#include "case_study/suite_run.hpp"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <omp.h>

#include "case_study/html_report.hpp"
#include "case_study/options.hpp"
#include "case_study/suite_record.hpp"
#include "case_study/summary.hpp"
#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/checksum.hpp"
#include "io/printable.hpp"
#include "io/format.hpp"
#include "io/progress.hpp"
#include "io/provenance.hpp"
#include "io/stop_signal.hpp"

namespace dlpverify::case_study {

namespace {

using json = nlohmann::json;

// Each study's name: its file's stem, a name given twice (a.toml in two folders) numbered
// " (2)", " (3)", … in the order of the files.
std::vector<std::string> study_names(const std::vector<std::string>& files) {
  std::vector<std::string> names;
  std::map<std::string, int> seen;
  for (const std::string& file : files) {
    std::string name = std::filesystem::path(file).stem().string();
    if (const int n = ++seen[name]; n > 1) name += " (" + std::to_string(n) + ")";
    names.push_back(name);
  }
  return names;
}

// The studies the journal holds, at their places; InputError naming the line that is not one of
// this suite's (the header already matched: same files, same contents, same build).
std::vector<std::optional<SuiteStudy>> journaled(const std::vector<json>& records, const std::vector<std::string>& names,
                                                 const std::string& json_file) {
  std::vector<std::optional<SuiteStudy>> studies(names.size());
  for (std::size_t line = 0; line < records.size(); ++line) {
    try {
      const std::size_t i = records[line].at("index").get<std::size_t>();
      SuiteStudy study = suite_study_from_json(records[line].at("study"));
      if (i >= names.size() || study.name != names[i] || studies[i])
        throw std::invalid_argument("study " + std::to_string(i) + " \"" + study.name + "\" is not one left to run");
      studies[i] = std::move(study);
    } catch (const std::exception& e) {
      throw InputError("--resume", journal_path(json_file),
                       "line " + std::to_string(line + 2) + " is not a study of this suite (" + record_fault(e) +
                           "); start over with --restart");
    }
  }
  return studies;
}

// The suite's JSON result: the summary, every study as its journal records it, the provenance.
std::string suite_json(const std::vector<SuiteStudy>& studies, int exit_code, const std::string& command_line) {
  json all = json::array();
  for (const SuiteStudy& s : studies) all.push_back(suite_study_json(s));
  const json result = {{"suite", {{"studies", studies.size()}, {"counts", suite_counts(studies)}, {"exit_code", exit_code}}},
                       {"studies", all},
                       {"provenance", provenance(command_line)}};
  return json_text(result, 2) + "\n";
}

// The outputs, all written or none.
void write_outputs(const SuiteRequest& request, const SuiteOutcome& outcome) {
  OutputSet outputs;
  if (wanted(request.junit_file)) outputs.add(request.junit_file, junit_xml(suite_junit(outcome.studies)));
  if (wanted(request.table_file)) outputs.add(request.table_file, outcome.table);
  if (wanted(request.summary_file)) outputs.add(request.summary_file, suite_summary(outcome.studies));
  if (wanted(request.html_file))
    outputs.add(request.html_file,
                html_report("suite of " + std::to_string(outcome.studies.size()) + " studies", outcome.studies));
  if (wanted(request.json_file))
    outputs.add(request.json_file, suite_json(outcome.studies, outcome.exit_code, request.command_line));
  outputs.commit();
}

// Progress lines are off while studies run side by side: one line rewritten in place cannot show two.
class ProgressOff {
 public:
  explicit ProgressOff(bool off) : saved_(progress::mode()) {
    if (off) progress::enable(progress::Mode::off);
  }
  ~ProgressOff() { progress::enable(saved_); }
  ProgressOff(const ProgressOff&) = delete;
  ProgressOff& operator=(const ProgressOff&) = delete;

 private:
  progress::Mode saved_;
};

}  // namespace

void validate(const SuiteRequest& request) {
  validate_threads(request.threads);
  const int most = 4 * omp_get_num_procs();
  if (request.jobs < 0 || request.jobs > most)
    throw InputError("--jobs", std::to_string(request.jobs), "must lie in [0, " + std::to_string(most) + "] (0: one study a thread)");
}

SuiteOutcome run_suite(const SuiteRequest& request, const StudyRunner& run, const StudyEnded& ended) {
  const std::vector<std::string> names = study_names(request.files);
  json checksums = json::array();
  for (const std::string& file : request.files) checksums.push_back(file_checksum(file));
  JournalTerms terms = journal_terms();
  // A study file whose bytes changed since the journal was written, by name (the files are the
  // same: the options, compared first, hold them).
  terms.study_change = [&request](const std::string& key, const json& here, const json& there) -> std::string {
    if (key != "study_file_fnv1a64" || !here.is_array() || !there.is_array() || here.size() != there.size()) return {};
    for (std::size_t i = 0; i < here.size() && i < request.files.size(); ++i)
      if (here[i] != there[i])
        return "study file " + printable(request.files[i]) + " changed since the journal was written: its content hash differs";
    return {};
  };
  StudyJournal journal(request.json_file, request.start, "suite", {{"files", request.files}},
                       {{"study_file_fnv1a64", checksums}}, terms);
  Progress<json> progress = journal.records();
  std::vector<std::optional<SuiteStudy>> studies = journaled(progress.done, names, request.json_file);

  std::vector<std::size_t> left;
  for (std::size_t i = 0; i < studies.size(); ++i)
    if (!studies[i]) left.push_back(i);
  std::size_t finished = studies.size() - left.size();
  const int threads = request.threads > 0 ? request.threads : omp_get_max_threads();
  const int jobs = static_cast<int>(std::clamp<std::size_t>(request.jobs > 0 ? request.jobs : threads, 1, std::max<std::size_t>(left.size(), 1)));
  const int share = jobs > 1 ? std::max(1, threads / jobs) : request.threads;  // 0: OpenMP's default

  StopOnSignal signals;
  const ProgressOff quiet(jobs > 1);
  std::mutex mutex;  // guards what follows, the journal and `ended`
  std::size_t next = 0;
  int stop_code = 0;  // 128 + N: a signal stopped a study, or asked the suite to stop
  std::exception_ptr failure;
  const auto work = [&] {
    if (share > 0) omp_set_num_threads(share);  // this thread's studies' OpenMP default
    for (;;) {
      std::size_t i = 0;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        if (failure || stop_code != 0 || next == left.size()) return;  // a signal after the last study stops nothing
        if (signals.signal() != 0) {
          stop_code = kExitStoppedBySignal + signals.signal();
          return;
        }
        i = left[next++];
      }
      SuiteStudy study = run(i);
      study.name = names[i];
      study.file = request.files[i];
      if (study.outcome) study.outcome->study = study.name;
      const std::lock_guard<std::mutex> lock(mutex);
      if (study.exit_code() >= kExitStoppedBySignal) {  // its own journal keeps its levels
        if (stop_code == 0) stop_code = study.exit_code();
        return;
      }
      try {
        if (progress.finished) progress.finished({{"index", i}, {"study", suite_study_json(study)}});
        studies[i] = std::move(study);
        ended(*studies[i], ++finished, studies.size());
      } catch (...) {
        if (!failure) failure = std::current_exception();
        return;
      }
    }
  };
  if (jobs == 1) {
    work();
  } else {
    std::vector<std::thread> workers;
    for (int j = 0; j < jobs; ++j) workers.emplace_back(work);
    for (std::thread& worker : workers) worker.join();
  }
  if (failure) std::rethrow_exception(failure);

  SuiteOutcome outcome;
  if (stop_code != 0) {
    const int code = journal.stopped(static_cast<int>(finished), static_cast<int>(studies.size()), "studies", jobs == 1);
    if (!journal.active())
      std::cerr << "dlpverify: " << signal_name(stop_code - kExitStoppedBySignal) << ": suite stopped after "
                << finished << " of " << studies.size() << " studies; none kept (--json keeps a journal to --resume)\n";
    outcome.exit_code = code > kExitStoppedBySignal ? code : stop_code;
    return outcome;
  }
  for (std::optional<SuiteStudy>& study : studies) outcome.studies.push_back(std::move(*study));
  outcome.table = suite_table(outcome.studies);
  outcome.exit_code = suite_exit_code(outcome.studies);
  write_outputs(request, outcome);
  journal.finish();
  return outcome;
}

}  // namespace dlpverify::case_study
