// The journal of a convergence study or a work-precision sweep: JSON Lines in
// <result>.journal.jsonl beside the study's JSON result. Its first line records everything that
// decides the result —
//   {"dlpverify_journal": 1, "command": "check",
//    "options": the study's options as its report shows them,
//    "study": case, its parameters, particles, t0, reference, duration, levels or runs, variables,
//    "build": version, commit, build type, compiler, SUNDIALS/Eigen/GSL, the executable's checksum}
// — and each further line one finished level (or run), exactly (harness/exact_record.hpp).
//
// An existing journal that holds finished levels is refused, never overwritten, unless the study
// resumes it or restarts; one that holds none (a study killed before its first level) is started
// over, as is the journal of a search, which records no levels. To resume, its first line must
// equal this run's, or the first thing that differs is named; its levels are then taken as they
// are. A file there that is not a journal is never removed. While a journal is open, SIGINT and
// SIGTERM stop the study after the level under way. The journal is removed by finish() once every
// output is written, kept when a signal stops the study or an output cannot be written, and
// removed on any other failure only if this run created it and finished no level (it then holds
// nothing).
//
// Under mpirun rank 0 alone keeps the journal: the levels it resumes from are sent to every rank,
// a stop is asked of every rank together (a signal seen by any rank stops all after the level under
// way), and only rank 0 records. Serially this is the journal alone.
#pragma once

#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/work_precision.hpp"
#include "io/journal_file.hpp"
#include "io/stop_signal.hpp"

namespace dlpverify {

// <result>.journal.jsonl; empty when the result goes to standard output or a device ("-", /dev/…,
// /proc/…, an existing file that is not a regular one), where no journal can sit beside it.
std::string journal_path(const std::string& result_file);

// What decides a result besides the options: the problem and its parameters, the reference and
// the plan; a convergence study adds its integrator, a sweep the labels of its runs.
nlohmann::json study_identity(const Problem& problem, const StudyPlan& plan, const ReferenceSettings& reference);

// The build: provenance less host, threads, date and command line, plus a checksum of the executable.
nlohmann::json build_identity();

// What happens to a journal found beside the result: kept unless it holds nothing (fresh),
// continued (resume) or discarded (restart).
enum class JournalStart { fresh, resume, restart };

// How the journal's errors and notices name what the user controls. The defaults are the API's
// words; a front end gives its own (the command line: --json, --resume, --restart, "option --").
struct JournalTerms {
  std::string result = "result file";             // the quantity naming the result the journal sits beside
  std::string resume = "JournalStart::resume";    // how a study is resumed
  std::string restart = "JournalStart::restart";  // how a study is started over
  std::string option = "option ";                 // before an option's key, where the first lines differ
  // Where a notice goes (resuming, a torn last line, a journal discarded, a stop): standard error
  // as "dlpverify: LINE" when empty.
  std::function<void(const std::string&)> notice;
  // How a difference in the study's identity under `key` reads, when the caller names it better
  // than by its two values (a suite's study file that changed); empty for the plain wording.
  std::function<std::string(const std::string& key, const nlohmann::json& here, const nlohmann::json& journal)> study_change;
};

// What was wrong with a journal's record, in the tool's words: a missing key is named, a value of
// the wrong kind says which kind it is and which belongs (a JSON library's exception, or any
// other's text, as it reads).
std::string record_fault(const std::exception& why);

// Refuses, before any work, a journal place the journal is never written through: a directory, or
// a symbolic link (InputError naming terms.result). Nothing on every rank but 0, or without a journal.
void check_journal_place(const std::string& result_file, const JournalTerms& terms);

class StudyJournal {
 public:
  // No journal (active() false) when journal_path(result_file) is empty, or on every rank but 0.
  // InputError naming terms.result (an existing journal with finished levels and start fresh; a
  // file that is not a journal), terms.resume (a journal of another study) or, for a start other
  // than fresh without a result file, a whole-message error naming terms.resume or terms.restart.
  StudyJournal(const std::string& result_file, JournalStart start, const std::string& command,
               const nlohmann::json& options, const nlohmann::json& study, JournalTerms terms = {});
  ~StudyJournal();
  StudyJournal(const StudyJournal&) = delete;
  StudyJournal& operator=(const StudyJournal&) = delete;

  bool active() const { return file_.has_value(); }

  // The levels to resume from, each new one recorded and a stop on a signal, shared by every rank.
  StudyProgress levels(const std::vector<Variable>& variables);
  // The same for the runs of a work-precision sweep.
  Progress<PrecisionRunResult> runs(const std::vector<Variable>& variables);
  // The same for results the caller writes and reads as JSON objects itself (a suite's studies).
  Progress<nlohmann::json> records();

  // Every output is written: the journal has done its work.
  void finish();
  // The study stopped on a signal after `done` of `total` `units` ("levels", "runs"): gives the
  // notice saying what the journal keeps and returns the exit code, 128 + the signal (on a rank
  // without the journal: 128, the command's outcome being rank 0's). `in_order` false: the `done`
  // finished are not the first ones (a suite's studies, finished side by side).
  int stopped(int done, int total, const std::string& units, bool in_order = true);
  // The results the journal holds, resumed and added: how many a level abandoned at a signal
  // leaves, which the level itself does not know.
  int kept() const;

 private:
  template <class Finished, class FromRecord, class ToRecord>
  Progress<Finished> progress(FromRecord from_record, ToRecord to_record);
  bool stop_requested() const;
  void record(const nlohmann::json& record);
  void notice(const std::string& line) const;
  [[noreturn]] void refuse_line(std::size_t line, const std::exception& why) const;

  JournalTerms terms_;
  std::optional<JournalFile> file_;
  std::optional<StopOnSignal> signals_;  // on the journal's rank, and on every rank while rank 0 keeps one
  bool created_ = false;                 // by this run
  int appended_ = 0;                     // results this run added
};

}  // namespace dlpverify
