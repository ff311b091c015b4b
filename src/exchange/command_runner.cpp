#include "exchange/command_runner.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "exchange/exchange_file.hpp"
#include "io/process.hpp"

namespace dlpverify::exchange {

namespace {

struct Descriptor {
  int fd = -1;
  explicit Descriptor(int f) : fd(f) {}
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
};

// The end of a memory file: its last `limit` bytes (the tail of stderr is what tells).
std::string tail(int fd, off_t limit) {
  const off_t size = ::lseek(fd, 0, SEEK_END);
  if (size <= 0) return {};
  const off_t from = size > limit ? size - limit : 0;
  std::string text(static_cast<std::size_t>(size - from), '\0');
  const ssize_t got = ::pread(fd, text.data(), text.size(), from);
  text.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  return text;
}

// Waits for pid until `deadline`; true when it ended (status set). A pidfd lets poll() sleep
// until the end or the deadline; without one (old kernels) we look every 10 ms.
bool wait_until(pid_t pid, std::chrono::steady_clock::time_point deadline, int& status) {
  const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
  const Descriptor guard(pidfd);
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) return true;
    if (done < 0 && errno != EINTR) return true;  // not our child any more: nothing to wait for
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    const int wait_ms = static_cast<int>(std::min<long long>(left.count(), pidfd >= 0 ? 1000 : 10));
    if (pidfd >= 0) {
      pollfd p{pidfd, POLLIN, 0};
      ::poll(&p, 1, wait_ms);
    } else {
      ::usleep(static_cast<useconds_t>(wait_ms) * 1000);
    }
  }
}

// While it lives, SIGINT, SIGTERM and SIGHUP at their default action (ending this process) are
// passed on to the program's process group and recorded instead; the handlers are restored after.
volatile std::sig_atomic_t forward_to_group = 0;
volatile std::sig_atomic_t forwarded_signal = 0;

extern "C" void forward_signal(int signal) {
  if (forward_to_group > 0) ::kill(-static_cast<pid_t>(forward_to_group), signal);
  forwarded_signal = signal;
}

class SignalForwarding {
 public:
  SignalForwarding() {
    forward_to_group = 0;
    forwarded_signal = 0;
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      struct sigaction current {};
      ::sigaction(kSignals[i], nullptr, &current);
      installed_[i] = current.sa_handler == SIG_DFL && (current.sa_flags & SA_SIGINFO) == 0;
      if (!installed_[i]) continue;
      struct sigaction forward {};
      forward.sa_handler = forward_signal;
      sigemptyset(&forward.sa_mask);
      ::sigaction(kSignals[i], &forward, &previous_[i]);
    }
  }
  // The program's group from now on; a signal that came before it existed goes to it at once.
  void to_group(pid_t group) {
    forward_to_group = group;
    if (forwarded_signal != 0) ::kill(-group, forwarded_signal);
  }
  int received() const { return forwarded_signal; }
  ~SignalForwarding() {
    forward_to_group = 0;
    for (std::size_t i = 0; i < kSignals.size(); ++i)
      if (installed_[i]) ::sigaction(kSignals[i], &previous_[i], nullptr);
  }
  SignalForwarding(const SignalForwarding&) = delete;
  SignalForwarding& operator=(const SignalForwarding&) = delete;

 private:
  static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
  std::array<bool, 3> installed_{};
  std::array<struct sigaction, 3> previous_{};
};

std::string ending_of(int status) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  return "exited with status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

std::string last_lines(const std::string& text, int lines) {
  std::vector<std::string> kept;
  std::size_t end = text.size();
  while (end > 0 && static_cast<int>(kept.size()) < lines) {
    const std::size_t start = text.rfind('\n', end - 1);
    const std::size_t from = start == std::string::npos ? 0 : start + 1;
    std::string line = text.substr(from, end - from);
    const auto first = line.find_first_not_of(" \t\r");
    const auto last = line.find_last_not_of(" \t\r");
    if (first != std::string::npos) kept.push_back(line.substr(first, last - first + 1));
    if (start == std::string::npos) break;
    end = start;
  }
  std::string joined;
  for (auto it = kept.rbegin(); it != kept.rend(); ++it) joined += (joined.empty() ? "" : " | ") + *it;
  return joined;
}

CommandResult run_command(const std::vector<std::string>& argv, double timeout_seconds) {
  Descriptor null_in(::open("/dev/null", O_RDONLY | O_CLOEXEC));
  Descriptor null_out(::open("/dev/null", O_WRONLY | O_CLOEXEC));
  Descriptor errors(::memfd_create("exec-stderr", MFD_CLOEXEC));
  if (null_in.fd < 0 || null_out.fd < 0 || errors.fd < 0)
    throw ExchangeError("cannot start " + argv.at(0) + ": " + std::strerror(errno));
  SignalForwarding forwarding;
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = -1;  // in a process group of its own: a timeout ends it and whatever it started
  if (const int failed = spawn_program(argv, null_in.fd, null_out.fd, errors.fd, true, pid))
    throw ExchangeError("cannot start " + argv[0] + ": " + std::strerror(failed));
  forwarding.to_group(pid);
  const auto deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                    std::chrono::duration<double>(timeout_seconds));
  int status = 0;
  CommandResult result;
  if (!wait_until(pid, deadline, status)) {
    ::kill(-pid, SIGKILL);  // the program and whatever it started
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    char limit[64];
    std::snprintf(limit, sizeof limit, "timed out after %g s", timeout_seconds);
    result.ending = limit;
  } else {
    result.success = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (!result.success) result.ending = ending_of(status);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.last_lines = last_lines(tail(errors.fd, 16384), 3);
  result.signal = forwarding.received();
  return result;
}

}  // namespace dlpverify::exchange
