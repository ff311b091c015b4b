#include "io/process.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <utility>

#include <fcntl.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"

extern char** environ;

namespace dlpverify {

namespace {

struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
  int release() { return std::exchange(fd, -1); }
};

// Blocks SIGPIPE in this thread while it lives; one raised meanwhile is consumed, not delivered.
// (Were SIGPIPE blocked already, a pending one is the caller's: it is left alone.)
class SigpipeBlock {
 public:
  SigpipeBlock() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
  }
  ~SigpipeBlock() {
    const timespec zero{0, 0};
    if (sigismember(&old_, SIGPIPE) == 0)
      while (sigtimedwait(&pipe_, nullptr, &zero) > 0) {
      }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlock(const SigpipeBlock&) = delete;
  SigpipeBlock& operator=(const SigpipeBlock&) = delete;

 private:
  sigset_t pipe_{}, old_{};
};

// A memory file's content from its start, up to `limit` bytes.
std::string read_all(int fd, std::size_t limit) {
  std::string text;
  if (::lseek(fd, 0, SEEK_SET) < 0) return text;
  char buffer[65536];
  while (text.size() < limit) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    text.append(buffer, static_cast<std::size_t>(got));
  }
  return text;
}

}  // namespace

int spawn_program(const std::vector<std::string>& argv, int in, int out, int err, bool own_group, pid_t& pid) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in, STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // The child starts with no signal blocked and every signal at its default action: none of ours
  // (SIGPIPE blocked while we feed it, SIGXFSZ ignored so that our writes fail instead) leaks in.
  posix_spawnattr_setflags(&attributes, static_cast<short>(POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF |
                                                           (own_group ? POSIX_SPAWN_SETPGROUP : 0)));
  if (own_group) posix_spawnattr_setpgroup(&attributes, 0);
  sigset_t none, every;
  sigemptyset(&none);
  sigfillset(&every);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &every);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid = -1;
  const int failed = ::posix_spawnp(&pid, args[0], &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return failed;
}

ProcessResult run_process(const std::vector<std::string>& argv, const std::function<bool(std::FILE*)>& feed) {
  if (argv.empty()) throw std::logic_error("run_process without a program");
  // All CLOEXEC: the child gets only the three dup2'ed onto its standard streams.
  FileDescriptor output{::memfd_create("child-stdout", MFD_CLOEXEC)};
  FileDescriptor errors{::memfd_create("child-stderr", MFD_CLOEXEC)};
  int ends[2] = {-1, -1};
  if (output.fd < 0 || errors.fd < 0 || ::pipe2(ends, O_CLOEXEC) != 0)
    throw SolverError("cannot run " + argv[0] + ": " + std::strerror(errno));
  FileDescriptor read_end{ends[0]}, write_end{ends[1]};
  pid_t pid = -1;
  if (const int failed = spawn_program(argv, read_end.fd, output.fd, errors.fd, false, pid))
    throw SolverError("cannot run " + argv[0] + ": " + std::strerror(failed));
  ::close(read_end.release());

  bool fed = false;
  {
    SigpipeBlock no_sigpipe;
    if (std::FILE* stream = ::fdopen(write_end.fd, "w")) {
      write_end.release();  // `feed` closes it
      try {
        fed = feed(stream);
      } catch (const std::exception&) {
        fed = false;
      }
    }
  }
  if (write_end.fd >= 0) ::close(write_end.release());  // fdopen failed: the child must see EOF

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw SolverError(argv[0] + ": " + std::strerror(errno));
  ProcessResult result;
  result.success = fed && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  result.output = read_all(output.fd, static_cast<std::size_t>(-1));
  result.errors = read_all(errors.fd, std::size_t{1} << 20);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  if (WIFSIGNALED(status))
    result.ending = "killed by signal " + std::to_string(WTERMSIG(status));
  else if (WEXITSTATUS(status) != 0)
    result.ending = "exited with status " + std::to_string(WEXITSTATUS(status));
  else if (!fed)
    result.ending = "stopped reading its input";
  return result;
}

}  // namespace dlpverify
