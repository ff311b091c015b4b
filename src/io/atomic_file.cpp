#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"

namespace dlpverify {

namespace fs = std::filesystem;

void check_output_path(const std::string& option, const std::string& path) {
  if (path.empty()) throw InputError(option, "\"\"", "empty file name");
  const fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw InputError(option, path, "is a directory, not a file");
  // The nearest folder that exists must be one we can write into.
  fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  while (!fs::exists(folder, ec)) {
    if (!folder.has_parent_path() || folder.parent_path() == folder) break;
    folder = folder.parent_path();
  }
  if (!fs::is_directory(folder, ec)) throw InputError(option, path, "its folder " + folder.string() + " is not a directory");
  // Unwritable is an output failure (exit 4), found before any work is done.
  if (::access(folder.c_str(), W_OK) != 0)
    throw OutputError(option + " = " + path + ": cannot write into folder " + folder.string() + " (" +
                      std::strerror(errno) + ")");
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const fs::path target(path);
  std::error_code ec;
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), ec);
  std::string pattern = (target.parent_path().empty() ? std::string(".") : target.parent_path().string()) + "/." +
                        target.filename().string() + ".tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw OutputError("cannot write " + path + ": " + std::strerror(errno));
  const char* data = content.data();
  std::size_t left = content.size();
  bool ok = true;
  while (left > 0 && ok) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0 && errno == EINTR) continue;
    ok = written > 0;
    if (ok) {
      data += written;
      left -= static_cast<std::size_t>(written);
    }
  }
  ok = ok && ::fsync(fd) == 0;
  // mkstemp makes the file 0600; results are for sharing, so give them the usual 0644 less umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ok = ::fchmod(fd, 0666 & ~mask) == 0 && ok;
  ok = ::close(fd) == 0 && ok;
  if (!ok || std::rename(name.data(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(name.data());
    throw OutputError("cannot write " + path + ": " + reason);
  }
}

}  // namespace dlpverify
