#include "io/standard_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"

namespace dlpverify {

void require_open_standard_output() {
  if (::fcntl(STDOUT_FILENO, F_GETFD) == -1 && errno == EBADF)
    throw OutputError("standard output is closed: what this run prints would be lost (redirect it, to /dev/null to discard)");
}

void check_standard_output() {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed) return;
  const int error = errno;
  throw OutputError(std::string("standard output: cannot be written") + (error ? std::string(": ") + std::strerror(error) : ""));
}

}  // namespace dlpverify
