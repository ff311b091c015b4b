#include "exchange/command_runner.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <mutex>
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
#include "io/process_tree.hpp"

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

// While it lives, SIGINT, SIGTERM and SIGHUP are ours. One that would end this process (its
// action is the default) is passed on to the program's process group and recorded; a second
// such signal kills the group (SIGKILL): a program that does not stop when asked is not waited
// for. One that has a handler (a journaled study's stop request) goes to that handler as it
// would have, and when that handler was installed to run once (SA_RESETHAND) the next one counts
// as at its default action, as it would have. An ignored one stays ignored. The handlers found
// are restored after (a handler that ran once, as the default action).
volatile std::sig_atomic_t forward_to_group = 0;
volatile std::sig_atomic_t forwarded_signal = 0;
constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
std::array<struct sigaction, 3> found_actions{};
std::array<volatile std::sig_atomic_t, 3> found_used{};  // a run-once handler that has run

extern "C" void forward_signal(int signal, siginfo_t* info, void* context) {
  const std::size_t i = signal == SIGINT ? 0 : signal == SIGTERM ? 1 : 2;
  const struct sigaction& found = found_actions[i];
  if (found.sa_handler == SIG_IGN) return;
  if (found.sa_handler != SIG_DFL && found_used[i] == 0) {
    if ((found.sa_flags & SA_RESETHAND) != 0) found_used[i] = 1;
    if ((found.sa_flags & SA_SIGINFO) != 0)
      found.sa_sigaction(signal, info, context);
    else
      found.sa_handler(signal);
    return;
  }
  const bool again = forwarded_signal != 0;
  if (forward_to_group > 0) ::kill(-static_cast<pid_t>(forward_to_group), again ? SIGKILL : signal);
  if (!again) forwarded_signal = signal;
}

class SignalForwarding {
 public:
  SignalForwarding() {
    forward_to_group = 0;
    forwarded_signal = 0;
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      found_used[i] = 0;
      ::sigaction(kSignals[i], nullptr, &found_actions[i]);
      struct sigaction forward {};
      forward.sa_sigaction = forward_signal;
      forward.sa_flags = SA_SIGINFO;
      sigemptyset(&forward.sa_mask);
      for (const int other : kSignals) sigaddset(&forward.sa_mask, other);  // one handler at a time
      ::sigaction(kSignals[i], &forward, nullptr);
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
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      struct sigaction restored = found_actions[i];
      if (found_used[i] != 0) restored.sa_handler = SIG_DFL, restored.sa_flags = 0;
      ::sigaction(kSignals[i], &restored, nullptr);
    }
  }
  SignalForwarding(const SignalForwarding&) = delete;
  SignalForwarding& operator=(const SignalForwarding&) = delete;
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
  // The signal forwarding and the reaping of descendants are the process's: one program at a time.
  static std::mutex one_program;
  const std::lock_guard<std::mutex> lock(one_program);
  Descriptor null_in(::open("/dev/null", O_RDONLY | O_CLOEXEC));
  Descriptor null_out(::open("/dev/null", O_WRONLY | O_CLOEXEC));
  Descriptor errors(::memfd_create("exec-stderr", MFD_CLOEXEC));
  if (null_in.fd < 0 || null_out.fd < 0 || errors.fd < 0)
    throw ExchangeError("cannot start " + argv.at(0) + ": " + std::strerror(errno));
  SignalForwarding forwarding;
  DescendantReaper descendants;  // what the program leaves behind, wherever it went
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
  descendants.end_all();  // the program has ended: nothing it started may outlive it
  result.last_lines = last_lines(tail(errors.fd, 16384), 3);
  result.signal = forwarding.received();
  return result;
}

}  // namespace dlpverify::exchange
