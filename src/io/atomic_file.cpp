#include "io/atomic_file.hpp"

#include <cerrno>
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

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string shown = printable(path);
  fs::path target;
  try {
    target = link_target("output", path);
  } catch (const InputError& e) {  // the path changed since it was checked
    throw OutputError("cannot write " + shown + ": " + e.reason());
  }
  std::error_code ec;
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), ec);
  std::string pattern = (target.parent_path().empty() ? std::string(".") : target.parent_path().string()) + "/." +
                        target.filename().string() + ".tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw OutputError("cannot write " + shown + ": " + std::strerror(errno));
  bool ok = write_all(fd, content);
  ok = ok && ::fsync(fd) == 0;
  // mkstemp makes the file 0600; results are for sharing, so give them the usual 0644 less umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ok = ::fchmod(fd, 0666 & ~mask) == 0 && ok;
  ok = ::close(fd) == 0 && ok;
  const int error = ok ? replace_regular(name.data(), target) : errno;
  if (error != 0) {
    ::unlink(name.data());
    if (ok && error == EEXIST)
      throw OutputError("cannot write " + shown + ": it is no longer a regular file; refusing to replace it");
    throw OutputError("cannot write " + shown + ": " + std::strerror(error));
  }
}

void write_output(const std::string& path, const std::string& content) {
  switch (output_target(path)) {
    case OutputTarget::discard: return;
    case OutputTarget::file: write_file_atomically(path, content); return;
    case OutputTarget::standard_output:
      std::cout.flush();
      std::fflush(stdout);
      if (!write_all(STDOUT_FILENO, content))
        throw OutputError("cannot write " + path + " (standard output): " + std::strerror(errno));
      return;
  }
}

}  // namespace dlpverify
