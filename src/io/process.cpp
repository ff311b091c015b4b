#include "io/process.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>

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
};

// Blocks SIGPIPE in this thread while we write; a SIGPIPE raised meanwhile is consumed before
// the mask is restored.
class SigpipeBlock {
 public:
  SigpipeBlock() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
    sigset_t pending;
    sigpending(&pending);
    was_pending_ = sigismember(&pending, SIGPIPE) == 1;
  }
  ~SigpipeBlock() {
    sigset_t pending;
    sigpending(&pending);
    if (!was_pending_ && sigismember(&pending, SIGPIPE) == 1) {
      const timespec zero{0, 0};
      sigtimedwait(&pipe_, nullptr, &zero);
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlock(const SigpipeBlock&) = delete;
  SigpipeBlock& operator=(const SigpipeBlock&) = delete;

 private:
  sigset_t pipe_{}, old_{};
  bool was_pending_ = false;
};

std::string read_all(int fd) {
  std::string text;
  if (::lseek(fd, 0, SEEK_SET) < 0) return text;
  char buffer[4096];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    text.append(buffer, static_cast<std::size_t>(got));
    if (text.size() > (1u << 20)) break;
  }
  return text;
}

}  // namespace

ProcessResult run_program(const std::vector<std::string>& argv, const std::string& folder,
                          const std::function<bool(std::FILE* input)>& feed) {
  ProcessResult result;
  FileDescriptor errors{::memfd_create("stderr", MFD_CLOEXEC)};
  if (errors.fd < 0) throw SolverError(std::string("cannot capture a program's messages: ") + std::strerror(errno));
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) throw SolverError(std::string("cannot make a pipe: ") + std::strerror(errno));
  FileDescriptor read_end{pipe_fds[0]}, write_end{pipe_fds[1]};

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, read_end.fd, STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, errors.fd, STDERR_FILENO);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  std::vector<std::string> arguments = argv;  // posix_spawnp takes char* const*
  std::vector<char*> pointers;
  for (std::string& a : arguments) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = ::posix_spawnp(&pid, pointers[0], &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    result.spawn_error = std::strerror(spawned);
    return result;
  }
  result.started = true;
  ::close(read_end.fd);
  read_end.fd = -1;

  {
    SigpipeBlock no_sigpipe;
    std::FILE* stream = ::fdopen(write_end.fd, "w");
    if (stream != nullptr) {
      write_end.fd = -1;  // feed owns the stream now, and closes it
      try {
        result.input_written = feed(stream);
      } catch (const std::exception&) {
        result.input_written = false;
      }
    } else {
      ::close(write_end.fd);
      write_end.fd = -1;
    }
  }

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw SolverError(std::string("waiting for ") + argv.front() + ": " + std::strerror(errno));
  result.exited = WIFEXITED(status);
  result.exit_status = result.exited ? WEXITSTATUS(status) : -1;
  result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  result.standard_error = read_all(errors.fd);
  return result;
}

}  // namespace dlpverify
