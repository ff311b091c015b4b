// An append-only JSON Lines file that survives being stopped at any instant (a study's journal,
// docs/cli.md, "The journal and --resume"). Each record is one write(2) of one complete line, then fsync(2):
// a reader finds whole lines and at most one torn last line — a write cut short has no newline
// yet — which it drops. The file is locked (flock) while open, so two runs cannot interleave.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dlpverify {

// Whether `path` is a study's journal: a regular file whose first line is a JSON object holding
// "dlpverify_journal", the header a study's journal begins with. Reads the first line alone, at
// most 1 MiB of it, without blocking; false for what it cannot open or read.
bool is_study_journal(const std::string& path);

class JournalFile {
 public:
  // Creates `path`, which must not exist yet (O_EXCL), in a folder that exists.
  // OutputError when it cannot, InputError when it appeared meanwhile.
  static JournalFile create(const std::string& path);
  // Opens an existing journal and reads its records, leaving out a torn last line (cut away at
  // the first append or clear, so a refusal changes nothing); nullopt when there is none. InputError when it is locked by another process or a complete
  // line is not a JSON object (naming the line), OutputError when it cannot be opened.
  static std::optional<JournalFile> open_existing(const std::string& path);

  JournalFile(JournalFile&& other) noexcept;
  JournalFile& operator=(JournalFile&&) = delete;
  JournalFile(const JournalFile&) = delete;
  ~JournalFile();

  const std::string& path() const { return path_; }
  const std::vector<nlohmann::json>& records() const { return records_; }  // as read, then appended
  bool found_torn_line() const { return found_torn_line_; }

  // One line, one write, fsync; OutputError on failure (the file is cut back to its last whole line).
  void append(const nlohmann::json& record);
  // Empties the file (to start it over when not even its first line is whole).
  void clear();
  // Deletes the file; the object stays usable only for records().
  void remove();

 private:
  JournalFile(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
  std::string path_;
  int fd_ = -1;
  long long size_ = 0;  // bytes of whole lines
  std::vector<nlohmann::json> records_;
  bool found_torn_line_ = false;
  bool torn_tail_ = false;  // bytes past size_ not yet cut away
};

}  // namespace dlpverify
