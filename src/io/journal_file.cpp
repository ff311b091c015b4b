#include "io/journal_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"
#include "io/input_file.hpp"

namespace dlpverify {

namespace fs = std::filesystem;

namespace {

std::string error_text() { return std::strerror(errno); }

// Exclusive and non-blocking: a second run on the same journal is refused, not queued.
void lock(int fd, const std::string& path) {
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return;
  const int error = errno;
  ::close(fd);
  if (error == EWOULDBLOCK) throw InputError("journal", path, "is in use by another running study");
  throw OutputError("cannot lock " + path + ": " + std::strerror(error));
}

// The folder's entry of a new file is durable only once the folder itself is synced.
void sync_folder(const fs::path& file) {
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

std::string read_all(int fd, const std::string& path) {
  std::string content;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::pread(fd, buffer, sizeof buffer, static_cast<off_t>(content.size()));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw OutputError("cannot read " + path + ": " + error_text());
    if (got == 0) return content;
    content.append(buffer, static_cast<std::size_t>(got));
  }
}

}  // namespace

bool is_study_journal(const std::string& path) {
  constexpr std::size_t kHeaderLimit = 1u << 20;  // a header holds the options, the study and the build: kilobytes
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return false;
  std::string line;
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
    char buffer[1 << 12];
    for (bool whole = false; !whole && line.size() < kHeaderLimit;) {
      const ssize_t got = ::read(fd, buffer, sizeof buffer);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) break;
      whole = std::memchr(buffer, '\n', static_cast<std::size_t>(got)) != nullptr;
      line.append(buffer, static_cast<std::size_t>(got));
    }
  }
  ::close(fd);
  const std::size_t end = line.find('\n');
  if (end == std::string::npos) return false;  // no whole first line: no header to lose
  const nlohmann::json header = nlohmann::json::parse(line.begin(), line.begin() + static_cast<long>(end), nullptr, false);
  return header.is_object() && header.contains("dlpverify_journal");
}

JournalFile JournalFile::create(const std::string& path) {
  const fs::path target(path);  // its folder exists: no command creates a folder
  const int fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0 && errno == EEXIST) throw InputError("journal", path, "appeared while this study was starting");
  if (fd < 0) throw OutputError("cannot create " + path + ": " + error_text());
  lock(fd, path);
  sync_folder(target);
  return JournalFile(path, fd);
}

std::optional<JournalFile> JournalFile::open_existing(const std::string& path) {
  // Without blocking, and checked on the descriptor: a journal is a regular file of bounded size
  // (a link to /dev/zero would be read without end).
  const int fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0 && errno == ENOENT) return std::nullopt;
  if (fd < 0) throw OutputError("cannot open " + path + ": " + error_text());
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw InputError("journal", path, "is not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) > input_limit::journal) {
    ::close(fd);
    throw InputError("journal", path, "is " + std::to_string(st.st_size) + " bytes, above the limit of 256 MiB");
  }
  ::fcntl(fd, F_SETFL, O_APPEND);  // blocking again
  lock(fd, path);
  JournalFile journal(path, fd);
  const std::string content = read_all(fd, path);
  std::size_t begin = 0;
  for (int line = 1;; ++line) {
    const std::size_t end = content.find('\n', begin);
    if (end == std::string::npos) break;  // the rest, if any, is a torn last line
    nlohmann::json record = nlohmann::json::parse(content.begin() + static_cast<long>(begin),
                                                  content.begin() + static_cast<long>(end), nullptr, false);
    if (record.is_discarded() || !record.is_object())
      throw InputError("journal", path, "line " + std::to_string(line) + " is not a JSON object: not a journal, or damaged");
    journal.records_.push_back(std::move(record));
    begin = end + 1;
  }
  journal.size_ = static_cast<long long>(begin);
  journal.found_torn_line_ = journal.torn_tail_ = begin < content.size();
  return journal;
}

JournalFile::JournalFile(JournalFile&& other) noexcept
    : path_(std::move(other.path_)),
      fd_(other.fd_),
      size_(other.size_),
      records_(std::move(other.records_)),
      found_torn_line_(other.found_torn_line_),
      torn_tail_(other.torn_tail_) {
  other.fd_ = -1;
}

JournalFile::~JournalFile() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

void JournalFile::append(const nlohmann::json& record) {
  if (fd_ < 0) throw OutputError("cannot append to " + path_ + ": it was removed");
  if (torn_tail_) {  // O_APPEND writes at the end: cut the torn line away first
    if (::ftruncate(fd_, static_cast<off_t>(size_)) != 0 || ::fsync(fd_) != 0)
      throw OutputError("cannot cut the torn last line of " + path_ + ": " + error_text());
    torn_tail_ = false;
  }
  // dump() never writes a raw newline; bytes that are not UTF-8 become U+FFFD instead of throwing.
  const std::string line = record.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  ssize_t written;
  do written = ::write(fd_, line.data(), line.size());
  while (written < 0 && errno == EINTR);
  const bool whole = written == static_cast<ssize_t>(line.size());
  const std::string reason = whole ? std::string() : written < 0 ? error_text() : std::string("short write");
  if (!whole || ::fsync(fd_) != 0) {
    const std::string why = whole ? error_text() : reason;
    if (::ftruncate(fd_, static_cast<off_t>(size_)) == 0) ::fsync(fd_);  // back to whole lines
    throw OutputError("cannot append to " + path_ + ": " + why);
  }
  size_ += static_cast<long long>(line.size());
  records_.push_back(record);
}

void JournalFile::clear() {
  if (::ftruncate(fd_, 0) != 0 || ::fsync(fd_) != 0) throw OutputError("cannot empty " + path_ + ": " + error_text());
  size_ = 0;
  torn_tail_ = false;
  records_.clear();
}

void JournalFile::remove() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still locked, so no other run reads it half-removed
  ::close(fd_);
  fd_ = -1;
}

}  // namespace dlpverify
