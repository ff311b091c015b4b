#include "study/journal.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <utility>

#include "dlpverify/case_report.hpp"
#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"
#include "harness/exact_record.hpp"
#include "io/checksum.hpp"
#include "io/format.hpp"
#include "io/printable.hpp"
#include "io/provenance.hpp"

namespace dlpverify {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kJournalFormat = 1;

std::string show(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

// How a difference in one section of the first line reads: "option --outer is 12 here, …"
// (`option`: "option --").
std::string describe(const std::string& option, const std::string& section, const std::string& key, const json* now,
                     const json* journal) {
  const std::string here = now ? show(*now) : "absent", there = journal ? show(*journal) : "absent";
  const std::string what = section == "options" ? option + key
                           : section == "build" ? "the build differs: its " + key
                                                : "the study differs: its " + key;
  return what + " is " + here + " here, " + there + " in the journal";
}

// The first thing in which the journal's first line differs from this run's; empty when none.
std::string first_difference(const json& journal, const json& now, const JournalTerms& terms) {
  const std::string& option = terms.option;
  if (journal.value("dlpverify_journal", json()) != now["dlpverify_journal"])
    return "it is not a dlpverify journal of format " + std::to_string(kJournalFormat);
  if (journal.value("command", json()) != now["command"])
    return "it is the journal of a " + show(journal.value("command", json())) + " study, this is " + show(now["command"]);
  for (const char* section : {"build", "options", "study"}) {
    const json& a = now[section];
    const json b = journal.contains(section) && journal[section].is_object() ? journal[section] : json::object();
    for (const auto& [key, value] : a.items()) {
      if (b.contains(key) && b[key] == value) continue;
      if (std::string(section) == "study" && b.contains(key) && terms.study_change)
        if (std::string change = terms.study_change(key, value, b[key]); !change.empty()) return change;
      return describe(option, section, key, &value, b.contains(key) ? &b[key] : nullptr);
    }
    for (const auto& [key, value] : b.items())
      if (!a.contains(key)) return describe(option, section, key, nullptr, &value);
  }
  return {};
}

// "a string", "an object".
std::string with_article(const std::string& kind) {
  return (kind.find_first_of("aeiou") == 0 ? "an " : "a ") + kind;
}

}  // namespace

std::string record_fault(const std::exception& why) {
  const auto* library = dynamic_cast<const json::exception*>(&why);
  if (!library) return why.what();
  // nlohmann's what() reads "[json.exception.KIND.ID] TEXT": its TEXT for the two a record meets.
  const std::string text = why.what();
  const std::string::size_type open = text.find("] ");
  const std::string detail = open == std::string::npos ? text : text.substr(open + 2);
  if (library->id == 403) {  // "key 'index' not found"
    const std::string::size_type first = detail.find('\''), last = detail.rfind('\'');
    if (first != std::string::npos && last > first)
      return "it has no \"" + detail.substr(first + 1, last - first - 1) + "\"";
  }
  if (library->id == 302) {  // "type must be number, but is string"
    const std::string::size_type must = detail.find("must be "), but = detail.find(", but is ");
    if (must != std::string::npos && but != std::string::npos && but > must)
      return "a value is " + with_article(detail.substr(but + 9)) + " where " +
             with_article(detail.substr(must + 8, but - must - 8)) + " belongs";
  }
  return "a value it holds is not of a study's result";
}

std::string journal_path(const std::string& result_file) {
  if (result_file.empty() || result_file == "-" || result_file.rfind("/dev/", 0) == 0 ||
      result_file.rfind("/proc/", 0) == 0)
    return {};
  std::error_code ec;
  const fs::file_status status = fs::status(result_file, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) return {};
  return result_file + ".journal.jsonl";
}

json study_identity(const Problem& problem, const StudyPlan& plan, const ReferenceSettings& reference) {
  json variables = json::array();
  for (const Variable& v : plan.variables) variables.push_back(v.name);
  json identity = {{"case", problem.name()},
          {"parameters", case_parameters(problem)},
          {"particles", problem.members()},
          {"t0", problem.initial_time()},
          {"reference", reference_kind_name(reference.kind)},
          {"reference_rtol", reference.rtol},
          {"t_end", plan.t_end},
          {"dt", plan.coarsest_dt},
          {"ratio", plan.ratio},
          {"levels", plan.levels},
          {"level_steps", level_steps(plan)},
          {"expected_order", plan.expected_order},
          {"variables", variables}};
  if (!plan.expected_order_by_variable.empty()) identity["expected_order_by_variable"] = plan.expected_order_by_variable;
  if (plan.precision == Precision::extended) identity["precision"] = to_string(plan.precision);  // levels of another arithmetic
  // An integrator reference is another study at another method or step.
  if (reference.kind == ReferenceKind::integrator && reference.integrator)
    identity.update({{"reference_integrator", reference.integrator->name()},
                     {"reference_integrator_order", reference.integrator->order()},
                     {"reference_dt", reference.dt}});
  return identity;
}

json build_identity() {
  json build = provenance("");
  for (const char* key : {"host", "threads", "date", "command_line"}) build.erase(key);
  build["executable_fnv1a64"] = file_checksum("/proc/self/exe");  // a rebuild keeps its version and commit, not its bytes
  return build;
}

void check_journal_place(const std::string& result_file, const JournalTerms& terms) {
  const std::string path = journal_path(result_file);
  if (distribution().rank() != 0 || path.empty()) return;
  std::error_code ec;
  const fs::file_status place = fs::symlink_status(path, ec);
  // A journal is removed and rewritten in place: through a link that would reach another study's
  // journal or a file elsewhere, so only a regular file (or nothing) is its place. A link to what
  // is no regular file is refused as that, by open_existing.
  const auto refuse_place = [&](const char* what) {
    throw InputError(terms.result, result_file,
                     "its journal's place " + printable(path) + " is " + what +
                         "; a journal is never written through one: move it away");
  };
  if (fs::is_directory(place)) refuse_place("a directory");
  const fs::file_status reached = fs::status(path, ec);
  if (fs::is_symlink(place) && (!fs::exists(reached) || fs::is_regular_file(reached))) refuse_place("a symbolic link");
}

StudyJournal::StudyJournal(const std::string& result_file, JournalStart start, const std::string& command,
                           const json& options, const json& study, JournalTerms terms)
    : terms_(std::move(terms)) {
  if (distribution().rank() != 0) return;  // rank 0's journal is every rank's (levels())
  const std::string path = journal_path(result_file);
  if (path.empty()) {
    if (start != JournalStart::fresh)
      throw InputError((start == JournalStart::resume ? terms_.resume : terms_.restart) + " needs " + terms_.result +
                       " naming a file: the journal lives beside it");
    return;
  }
  check_journal_place(result_file, terms_);  // before the header's checksum of the executable
  // The first line as it will read back (bytes that are not UTF-8 become U+FFFD).
  const json header = json::parse(show({{"dlpverify_journal", kJournalFormat},
                                        {"command", command},
                                        {"options", options},
                                        {"study", study},
                                        {"build", build_identity()}}));
  std::error_code ec;
  const fs::file_status place = fs::symlink_status(path, ec);
  if (fs::exists(place))
    if (std::optional<JournalFile> existing = JournalFile::open_existing(path)) file_.emplace(std::move(*existing));
  const std::size_t finished = file_ && !file_->records().empty() ? file_->records().size() - 1 : 0;
  if (file_ && !file_->records().empty() && !file_->records().front().contains("dlpverify_journal"))
    throw InputError(terms_.result, result_file,
                     path + " beside it is not a dlpverify journal; move it away, it is not removed");
  if (finished > 0 && start == JournalStart::fresh)
    throw InputError(terms_.result, result_file,
                     "the journal of an unfinished study is beside it (" + path + ", " + std::to_string(finished) +
                         " finished): continue that study with " + terms_.resume + ", or start over with " +
                         terms_.restart);
  if (finished > 0 && start == JournalStart::resume) {
    const std::string difference = first_difference(file_->records().front(), header, terms_);
    if (!difference.empty())
      throw InputError(terms_.resume, path,
                       difference + "; resume with the journal's options and build, or start over with " + terms_.restart);
    if (file_->found_torn_line()) notice(path + ": its last line was cut short (a write interrupted), left out");
    notice("resuming from " + path + " (" + std::to_string(finished) + " finished, taken as they are)");
    signals_.emplace();
    return;
  }
  if (finished > 0) notice(terms_.restart + ": " + path + " (" + std::to_string(finished) + " finished) discarded");
  // A new journal, one that holds no finished level, or one --restart discards: start it over.
  if (file_) file_->clear();
  else file_.emplace(JournalFile::create(path));
  created_ = true;
  try {
    file_->append(header);
  } catch (...) {
    file_->remove();
    throw;
  }
  signals_.emplace();
}

StudyJournal::~StudyJournal() {
  if (file_ && created_ && appended_ == 0) file_->remove();  // it holds nothing
}

void StudyJournal::record(const json& record) {
  if (!file_) return;
  file_->append(record);
  ++appended_;
}

void StudyJournal::notice(const std::string& line) const {
  if (terms_.notice)
    terms_.notice(line);
  else
    std::cerr << "dlpverify: " << line << "\n";
}

int StudyJournal::kept() const {
  // The file's records as read, then appended, after the header.
  return file_ && !file_->records().empty() ? static_cast<int>(file_->records().size()) - 1 : 0;
}

bool StudyJournal::stop_requested() const { return signals_ && signals_->signal() != 0; }

void StudyJournal::refuse_line(std::size_t line, const std::exception& why) const {
  throw InputError(terms_.resume, file_->path(),
                   "line " + std::to_string(line) + " is not a result of this study (" + record_fault(why) +
                       "); start over with " + terms_.restart);
}

// Rank 0's records are every rank's: its finished results are sent to the others as records, and
// a stop is asked of every rank together.
template <class Finished, class FromRecord, class ToRecord>
Progress<Finished> StudyJournal::progress(FromRecord from_record, ToRecord to_record) {
  Progress<Finished> own;
  if (file_) {
    const std::vector<json>& records = file_->records();
    for (std::size_t line = 1; line < records.size(); ++line) {
      try {
        own.done.push_back(from_record(records[line]));
      } catch (const std::exception& e) {
        refuse_line(line + 1, e);
      }
    }
    own.finished = [this, to_record](const Finished& finished) { record(to_record(finished)); };
    own.stop = [this] { return stop_requested(); };
  }
  const Distribution& all = distribution();
  if (all.ranks() == 1) return own;
  StopOnSignal::share_levels();
  json sent = {{"journal", active()}, {"done", json::array()}};
  for (const Finished& finished : own.done) sent["done"].push_back(to_record(finished));
  const json received = json::parse(all.from_root(sent.dump()));
  Progress<Finished> shared;
  for (const json& record : received.at("done")) shared.done.push_back(from_record(record));
  if (all.rank() == 0)
    shared.finished = own.finished;
  else if (received.at("journal").get<bool>())
    signals_.emplace();  // SIGINT and SIGTERM stop every rank, as rank 0's journal does
  shared.stop = [this, &all] { return all.any(stop_requested()); };
  return shared;
}

StudyProgress StudyJournal::levels(const std::vector<Variable>& variables) {
  return progress<LevelResult>([&variables](const json& record) { return level_from_record(record, variables); },
                               [variables](const LevelResult& level) { return level_record(level, variables); });
}

Progress<PrecisionRunResult> StudyJournal::runs(const std::vector<Variable>& variables) {
  return progress<PrecisionRunResult>(
      [&variables](const json& record) { return run_from_record(record, variables); },
      [variables](const PrecisionRunResult& run) { return run_record(run, variables); });
}

Progress<json> StudyJournal::records() {
  return progress<json>([](const json& record) { return record; }, [](const json& record) { return record; });
}

void StudyJournal::finish() {
  if (file_) file_->remove();
}

int StudyJournal::stopped(int done, int total, const std::string& units, bool in_order) {
  if (!file_) return kExitStoppedBySignal;
  const int signal = signals_ ? signals_->signal() : 0;
  std::string line = signal_name(signal) + ": stopped ";
  if (created_ && appended_ == 0) {
    file_->remove();
    line += "before the first of its " + units + " finished; nothing to keep";
  } else {
    line += "after " + std::to_string(done) + " of " + std::to_string(total) + " " + units + "; " + file_->path() +
            " keeps " +
            (done == 0  ? "none yet"
             : in_order ? (done == 1 ? "the first" : "the first " + std::to_string(done))
                        : (done == 1 ? "the one" : "those " + std::to_string(done)) + " finished") +
            ": continue with " + terms_.resume;
  }
  notice(line);
  return kExitStoppedBySignal + signal;
}

}  // namespace dlpverify
