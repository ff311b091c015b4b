#include "io/atomic_file.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"
#include "io/printable.hpp"

namespace dlpverify {

namespace fs = std::filesystem;

namespace {

// Writes all of `content` to `fd`; false on an error (errno set).
bool write_all(int fd, const std::string& content) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return true;
}

// Renames the finished temporary file onto `target` unless something other than a regular file
// is there: onto nothing without replacing what may appear meanwhile (RENAME_NOREPLACE), onto a
// regular file by rename(2). Returns 0, or the errno; EEXIST for a non-regular target.
int replace_regular(const char* temporary, const fs::path& target) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    struct stat existing {};
    if (::lstat(target.c_str(), &existing) == 0) {
      if (!S_ISREG(existing.st_mode)) return EEXIST;
      return std::rename(temporary, target.c_str()) == 0 ? 0 : errno;
    }
    if (::renameat2(AT_FDCWD, temporary, AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0) return 0;
    if (errno == EINVAL || errno == ENOSYS)  // a file system or kernel without RENAME_NOREPLACE
      return std::rename(temporary, target.c_str()) == 0 ? 0 : errno;
    if (errno != EEXIST) return errno;
  }
  return EEXIST;
}

// Writes `content` to a new temporary file beside `target` and flushes it to disk; returns its
// name, or throws OutputError naming `shown` (no temporary is left).
std::string write_temporary(const fs::path& target, const std::string& shown, const std::string& content) {
  std::string pattern = (target.parent_path().empty() ? std::string(".") : target.parent_path().string()) + "/." +
                        target.filename().string() + ".tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw OutputError("cannot write " + shown + ": " + std::strerror(errno));
  bool ok = write_all(fd, content);
  int error = ok ? 0 : errno;
  if (ok && ::fsync(fd) != 0) ok = false, error = errno;
  // mkstemp makes the file 0600; results are for sharing, so give them the usual 0644 less umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (ok && ::fchmod(fd, 0666 & ~mask) != 0) ok = false, error = errno;
  if (::close(fd) != 0 && ok) ok = false, error = errno;
  if (!ok) {
    ::unlink(name.data());
    throw OutputError("cannot write " + shown + ": " + std::strerror(error));
  }
  return name.data();
}

// What a commit keeps of the file it replaces: whether there was one, and a hard link to it
// beside the target (empty when the file system takes no hard links: then a failure later in the
// same commit cannot put that file back, and leaves the new one).
struct OldFile {
  bool existed = false;
  std::string link;
};

OldFile keep_old(const std::string& target) {
  struct stat existing {};
  if (::lstat(target.c_str(), &existing) != 0 || !S_ISREG(existing.st_mode)) return {};
  const fs::path path(target);
  for (int attempt = 0; attempt < 100; ++attempt) {
    // Appended piece by piece: GCC 12 misreads "." + std::string&& as an overlapping copy (-Wrestrict).
    std::string leaf = ".";
    leaf += path.filename().string();
    leaf += ".old." + std::to_string(::getpid()) + "." + std::to_string(attempt);
    const std::string name = (path.parent_path() / leaf).string();
    if (::link(target.c_str(), name.c_str()) == 0) return {true, name};
    if (errno != EEXIST) break;
  }
  return {true, {}};
}

// Puts `old` back at `target`, which a commit has replaced: the old file, or nothing when there
// was none.
void restore(const std::string& target, OldFile& old) {
  if (!old.existed) {
    ::unlink(target.c_str());
  } else if (!old.link.empty() && std::rename(old.link.c_str(), target.c_str()) == 0) {
    old.link.clear();
  }
}

}  // namespace

OutputSet::~OutputSet() {
  if (committed_) return;
  for (const Staged& file : files_) ::unlink(file.temporary.c_str());
}

void OutputSet::add(const std::string& path, const std::string& content) {
  switch (output_target(path)) {
    case OutputTarget::discard: return;
    case OutputTarget::standard_output: standard_output_.push_back(content); return;
    case OutputTarget::file: break;
  }
  const std::string shown = printable(path);
  fs::path target;
  try {
    target = link_target("output", path);
  } catch (const InputError& e) {  // the path changed since it was checked
    throw OutputError("cannot write " + shown + ": " + e.reason());
  }
  files_.push_back({shown, target.string(), write_temporary(target, shown, content)});
}

void OutputSet::commit() {
  if (committed_) return;
  for (const std::string& content : standard_output_) {
    std::cout.flush();
    std::fflush(stdout);
    if (!write_all(STDOUT_FILENO, content))
      throw OutputError(std::string("cannot write standard output: ") + std::strerror(errno));
  }
  std::vector<OldFile> old(files_.size());
  for (std::size_t i = 0; i < files_.size(); ++i) old[i] = keep_old(files_[i].target);
  int error = 0;
  std::size_t failed = 0;  // the first output not renamed into place
  while (failed < files_.size() && (error = replace_regular(files_[failed].temporary.c_str(), files_[failed].target)) == 0)
    ++failed;
  if (error != 0) {
    for (std::size_t j = 0; j < failed; ++j) restore(files_[j].target, old[j]);
    for (std::size_t j = failed; j < files_.size(); ++j) ::unlink(files_[j].temporary.c_str());
  }
  for (const OldFile& file : old)
    if (!file.link.empty()) ::unlink(file.link.c_str());
  committed_ = true;  // nothing of the set is left to remove
  if (error == EEXIST)
    throw OutputError("cannot write " + files_[failed].shown + ": it is no longer a regular file; refusing to replace it");
  if (error != 0) throw OutputError("cannot write " + files_[failed].shown + ": " + std::strerror(error));
}

void write_output(const std::string& path, const std::string& content) {
  OutputSet set;
  set.add(path, content);
  set.commit();
}

void report_file_size_limit_as_error() { std::signal(SIGXFSZ, SIG_IGN); }

}  // namespace dlpverify
