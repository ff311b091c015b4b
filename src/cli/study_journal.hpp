// The journal of a `converge`, `check` or `precision` study (docs/cli.md, "The journal and --resume"): JSON
// Lines in <json>.journal.jsonl beside the final JSON. Its first line records everything that
// decides the result —
//   {"dlpverify_journal": 1, "command": "check",
//    "options": every option after the case's defaults are filled in (as in the JSON's "options"),
//    "study": case, its parameters, particles, t0, reference, duration, levels or runs, variables,
//    "build": version, commit, build type, compiler, SUNDIALS/Eigen/GSL, the executable's checksum}
// — and each further line one finished level (or run), exactly (harness/exact_record.hpp).
//
// An existing journal that holds finished levels is refused (exit 2), never overwritten, unless
// --resume continues it or --restart discards it; one that holds none (a study killed before its
// first level) is started over, as is the journal of a search, which records no levels. With
// --resume its first line must equal this run's, or the first thing that differs is named (exit 2);
// its levels are then taken as they are. A file there that is not a journal is never removed. While a journal is open, SIGINT and SIGTERM stop the study after the
// level under way (exit 128 + the signal). The journal is removed once every output is written,
// kept when a signal stops the study or an output cannot be written, and removed on any other
// failure only if this run created it and finished no level (it then holds nothing).
#pragma once

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"
#include "dlpverify/integrator.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"
#include "io/journal_file.hpp"
#include "io/stop_signal.hpp"

namespace dlpverify::cli {

// <json>.journal.jsonl; empty when the JSON goes to standard output or a device ("-", /dev/…,
// /proc/…, an existing file that is not a regular one), where no journal can sit beside it.
std::string journal_path(const std::string& json_file);

// What decides a result besides the options: the problem and its parameters, the reference and
// the plan; a convergence study adds its integrator, a sweep the labels of its runs.
nlohmann::json study_identity(const Problem& problem, const StudyPlan& plan, const ReferenceSettings& reference);

// The build: provenance less host, threads, date and command line, plus a checksum of the executable.
nlohmann::json build_identity();

// What happens to a journal found beside --json: kept unless it holds nothing (fresh), continued
// (--resume) or discarded (--restart).
enum class JournalStart { fresh, resume, restart };
JournalStart journal_start(bool resume, bool restart);

class StudyJournal {
 public:
  // No journal (active() false) when journal_path(json_file) is empty. InputError naming --json
  // (an existing journal with finished levels and no --resume or --restart; a file that is not a
  // journal), --resume (a journal of another study) or --restart.
  StudyJournal(const std::string& json_file, JournalStart start, const std::string& command,
               const nlohmann::json& options, const nlohmann::json& study);
  ~StudyJournal();
  StudyJournal(const StudyJournal&) = delete;
  StudyJournal& operator=(const StudyJournal&) = delete;

  bool active() const { return file_.has_value(); }

  // The finished results to resume from, and each new one recorded as `to_record` writes it;
  // `from_record` (throwing on a malformed record) reads them back. Stops on a signal.
  template <class Finished, class FromRecord, class ToRecord>
  Progress<Finished> progress(FromRecord from_record, ToRecord to_record);

  bool stop_requested() const { return signals_ && signals_->signal() != 0; }
  // Every output is written: the journal has done its work.
  void finish();
  // The study stopped on a signal after `done` of `total` `units` ("levels", "runs"): prints the
  // one line saying what the journal keeps and returns the exit code, 128 + the signal.
  int stopped(int done, int total, const std::string& units);

 private:
  void record(const nlohmann::json& record);
  [[noreturn]] void refuse_line(std::size_t line, const std::exception& why) const;

  std::optional<JournalFile> file_;
  std::optional<StopOnSignal> signals_;
  bool created_ = false;  // by this run
  int appended_ = 0;      // results this run added
};

template <class Finished, class FromRecord, class ToRecord>
Progress<Finished> StudyJournal::progress(FromRecord from_record, ToRecord to_record) {
  Progress<Finished> progress;
  if (!file_) return progress;
  const std::vector<nlohmann::json>& records = file_->records();
  for (std::size_t line = 1; line < records.size(); ++line) {
    try {
      progress.done.push_back(from_record(records[line]));
    } catch (const std::exception& e) {
      refuse_line(line + 1, e);
    }
  }
  progress.finished = [this, to_record](const Finished& finished) { record(to_record(finished)); };
  progress.stop = [this] { return stop_requested(); };
  return progress;
}

}  // namespace dlpverify::cli
