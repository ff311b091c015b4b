#include "io/input_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"

namespace dlpverify {

namespace {

std::string what_it_is(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string bytes_text(std::uintmax_t bytes) {
  if (bytes >= (1u << 30) && bytes % (1u << 30) == 0) return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

int open_input_file(const std::string& kind, const std::string& path, std::uintmax_t limit) {
  if (path.empty()) throw InputError(kind, "''", "is empty; name a file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    throw InputError(kind, path, std::string("cannot be read: ") + (error == ENOENT ? "no such file" : std::strerror(error)));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const mode_t mode = st.st_mode;
    ::close(fd);
    throw InputError(kind, path, "is " + what_it_is(mode) + ", not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) > limit) {
    ::close(fd);
    throw InputError(kind, path, "is " + std::to_string(st.st_size) + " bytes, above the limit of " + bytes_text(limit));
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}

std::string read_input_file(const std::string& kind, const std::string& path, std::uintmax_t limit) {
  const int fd = open_input_file(kind, path, limit);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      throw InputError(kind, path, std::string("cannot be read: ") + std::strerror(error));
    }
    if (text.size() + static_cast<std::size_t>(n) > limit) {
      ::close(fd);
      throw InputError(kind, path, "grew above the limit of " + bytes_text(limit) + " while it was read");
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

std::ifstream open_input_stream(const std::string& kind, const std::string& path, std::uintmax_t limit) {
  const int fd = open_input_file(kind, path, limit);
  std::ifstream in("/proc/self/fd/" + std::to_string(fd), std::ios::binary);
  ::close(fd);
  if (!in) throw InputError(kind, path, "cannot be read");
  return in;
}

void check_input_file(const std::string& kind, const std::string& path, std::uintmax_t limit) {
  ::close(open_input_file(kind, path, limit));
}

}  // namespace dlpverify
