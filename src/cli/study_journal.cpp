#include "cli/study_journal.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "dlpverify/case_report.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "io/stop_signal.hpp"

namespace dlpverify::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kJournalFormat = 1;

std::string show(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

// FNV-1a (64 bit) of the running executable: a rebuild with uncommitted changes keeps its
// version and commit, not its bytes.
std::string executable_checksum() {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  if (!in) return "unknown";
  std::uint64_t hash = 14695981039346656037ull;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 1099511628211ull;
    }
  return printf_string("%016llx", static_cast<unsigned long long>(hash));
}

// How a difference in one section of the first line reads: "option --outer is 12 here, …".
std::string describe(const std::string& section, const std::string& key, const json* now, const json* journal) {
  const std::string here = now ? show(*now) : "absent", there = journal ? show(*journal) : "absent";
  const std::string what = section == "options" ? "option --" + key
                           : section == "build" ? "the build differs: its " + key
                                                : "the study differs: its " + key;
  return what + " is " + here + " here, " + there + " in the journal";
}

// The first thing in which the journal's first line differs from this run's; empty when none.
std::string first_difference(const json& journal, const json& now) {
  if (journal.value("dlpverify_journal", json()) != now["dlpverify_journal"])
    return "it is not a dlpverify journal of format " + std::to_string(kJournalFormat);
  if (journal.value("command", json()) != now["command"])
    return "it is the journal of a " + show(journal.value("command", json())) + " study, this is " + show(now["command"]);
  for (const char* section : {"build", "options", "study"}) {
    const json& a = now[section];
    const json b = journal.contains(section) && journal[section].is_object() ? journal[section] : json::object();
    for (const auto& [key, value] : a.items())
      if (!b.contains(key) || b[key] != value) return describe(section, key, &value, b.contains(key) ? &b[key] : nullptr);
    for (const auto& [key, value] : b.items())
      if (!a.contains(key)) return describe(section, key, nullptr, &value);
  }
  return {};
}

}  // namespace

std::string journal_path(const std::string& json_file) {
  if (json_file.empty() || json_file == "-" || json_file.rfind("/dev/", 0) == 0 || json_file.rfind("/proc/", 0) == 0)
    return {};
  std::error_code ec;
  const fs::file_status status = fs::status(json_file, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) return {};
  return json_file + ".journal.jsonl";
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
  build["executable_fnv1a64"] = executable_checksum();
  return build;
}

JournalStart journal_start(bool resume, bool restart) {
  return resume ? JournalStart::resume : restart ? JournalStart::restart : JournalStart::fresh;
}

StudyJournal::StudyJournal(const std::string& json_file, JournalStart start, const std::string& command,
                           const json& options, const json& study) {
  const std::string path = journal_path(json_file);
  if (path.empty()) {
    if (start != JournalStart::fresh)
      throw InputError(std::string(start == JournalStart::resume ? "--resume" : "--restart") +
                       " needs --json naming a file: the journal lives beside it");
    return;
  }
  // The first line as it will read back (bytes that are not UTF-8 become U+FFFD).
  const json header = json::parse(show({{"dlpverify_journal", kJournalFormat},
                                        {"command", command},
                                        {"options", options},
                                        {"study", study},
                                        {"build", build_identity()}}));
  std::error_code ec;
  if (fs::exists(fs::symlink_status(path, ec)))
    if (std::optional<JournalFile> existing = JournalFile::open_existing(path)) file_.emplace(std::move(*existing));
  const std::size_t finished = file_ && !file_->records().empty() ? file_->records().size() - 1 : 0;
  if (file_ && !file_->records().empty() && !file_->records().front().contains("dlpverify_journal"))
    throw InputError("--json", json_file,
                     path + " beside it is not a dlpverify journal; move it away, it is not removed");
  if (finished > 0 && start == JournalStart::fresh)
    throw InputError("--json", json_file,
                     "the journal of an unfinished study is beside it (" + path + ", " + std::to_string(finished) +
                         " finished): continue that study with --resume, or start over with --restart");
  if (finished > 0 && start == JournalStart::resume) {
    const std::string difference = first_difference(file_->records().front(), header);
    if (!difference.empty())
      throw InputError("--resume", path, difference + "; resume with the journal's options and build, or start over with --restart");
    if (file_->found_torn_line())
      std::cerr << "dlpverify: " << path << ": its last line was cut short (a write interrupted), left out\n";
    std::cerr << "dlpverify: resuming from " << path << " (" << finished << " finished, taken as they are)\n";
    signals_.emplace();
    return;
  }
  if (finished > 0) std::cerr << "dlpverify: --restart: " << path << " (" << finished << " finished) discarded\n";
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

void StudyJournal::refuse_line(std::size_t line, const std::exception& why) const {
  throw InputError("--resume", file_->path(),
                   "line " + std::to_string(line) + " is not a result of this study (" + why.what() +
                       "); start over with --restart");
}

void StudyJournal::finish() {
  if (file_) file_->remove();
}

int StudyJournal::stopped(int done, int total, const std::string& units) {
  const int signal = signals_ ? signals_->signal() : 0;
  std::string line = "dlpverify: " + signal_name(signal) + ": stopped ";
  if (created_ && appended_ == 0) {
    file_->remove();
    line += "before the first of its " + units + " finished; nothing to keep";
  } else {
    line += "after " + std::to_string(done) + " of " + std::to_string(total) + " " + units + "; " + file_->path() +
            " keeps " + (done == 0 ? "none yet" : done == 1 ? "the first" : "the first " + std::to_string(done)) +
            ": continue with --resume";
  }
  std::cerr << line << "\n";
  return kExitStoppedBySignal + signal;
}

}  // namespace dlpverify::cli
