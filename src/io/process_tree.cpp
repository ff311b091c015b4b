#include "io/process_tree.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <dirent.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

namespace dlpverify {

namespace {

struct Process {
  pid_t pid = 0;
  pid_t parent = 0;
  unsigned long long start = 0;  // start time in clock ticks since boot: with pid, who it is
};

// /proc/PID/stat's parent and start time (fields 4 and 22); false when the process is gone.
// The name (field 2) may hold blanks and parentheses: the fields are counted after its last ')'.
bool read_stat(pid_t pid, Process& process) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return false;
  const std::size_t name_end = line.rfind(')');
  if (name_end == std::string::npos) return false;
  std::istringstream fields(line.substr(name_end + 1));
  std::string field;
  for (int number = 3; number <= 22 && fields >> field; ++number) {
    if (number == 4) process.parent = static_cast<pid_t>(std::strtol(field.c_str(), nullptr, 10));
    if (number == 22) process.start = std::strtoull(field.c_str(), nullptr, 10);
  }
  process.pid = pid;
  return static_cast<bool>(fields);
}

// Every process /proc shows now.
std::vector<Process> processes() {
  std::vector<Process> all;
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return all;
  while (const dirent* entry = ::readdir(proc)) {
    char* end = nullptr;
    const long pid = std::strtol(entry->d_name, &end, 10);
    Process process;
    if (pid > 0 && *end == '\0' && read_stat(static_cast<pid_t>(pid), process)) all.push_back(process);
  }
  ::closedir(proc);
  return all;
}

// SIGKILL to `process` if it is still the one /proc showed: the pidfd pins it, its start time
// (read after) tells whether the pid was reused before. Kernels without pidfds get a plain kill.
void kill_exactly(const Process& process) {
  const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, process.pid, 0));
  if (pidfd < 0) {
    if (errno == ENOSYS) ::kill(process.pid, SIGKILL);
    return;  // ESRCH: gone already
  }
  Process now;
  if (read_stat(process.pid, now) && now.start == process.start)
    ::syscall(SYS_pidfd_send_signal, pidfd, SIGKILL, nullptr, 0);
  ::close(pidfd);
}

// The children of this process /proc shows now.
std::vector<Process> children(const std::vector<Process>& all) {
  std::vector<Process> ours;
  std::copy_if(all.begin(), all.end(), std::back_inserter(ours), [](const Process& p) { return p.parent == ::getpid(); });
  return ours;
}

}  // namespace

DescendantReaper::DescendantReaper() {
  for (const Process& child : children(processes())) kept_.emplace_back(child.pid, child.start);
  ::prctl(PR_GET_CHILD_SUBREAPER, &previous_, 0, 0, 0);
  ::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
}

DescendantReaper::~DescendantReaper() {
  try {
    end_all();
  } catch (...) {  // out of memory while reading /proc: nothing better to do in a destructor
  }
  ::prctl(PR_SET_CHILD_SUBREAPER, previous_, 0, 0, 0);
}

// Each round kills the children not kept and all below them, then reaps those children: what
// was below them comes to us (we are the subreaper) and is found, killed already, next round.
// A process forked meanwhile is below a killed one, so it comes to us too; the rounds end when
// a round finds no child to end.
void DescendantReaper::end_all() {
  for (;;) {
    const std::vector<Process> all = processes();
    std::multimap<pid_t, Process> by_parent;
    for (const Process& p : all) by_parent.emplace(p.parent, p);
    std::vector<Process> roots;
    for (const Process& child : children(all))
      if (std::find(kept_.begin(), kept_.end(), std::make_pair(child.pid, child.start)) == kept_.end())
        roots.push_back(child);
    if (roots.empty()) return;
    std::vector<Process> doomed = roots;
    std::set<pid_t> seen;  // a snapshot of /proc is not atomic: never walk a loop twice
    for (std::size_t i = 0; i < doomed.size(); ++i) {
      if (!seen.insert(doomed[i].pid).second) continue;
      const auto [from, to] = by_parent.equal_range(doomed[i].pid);
      for (auto it = from; it != to; ++it) doomed.push_back(it->second);
    }
    for (std::size_t i = 0; i < doomed.size(); ++i) {
      if (i < roots.size())
        ::kill(doomed[i].pid, SIGKILL);  // our child: its pid is not reused before we reap it
      else
        kill_exactly(doomed[i]);
    }
    for (const Process& root : roots)
      while (::waitpid(root.pid, nullptr, 0) < 0 && errno == EINTR) {
      }
  }
}

}  // namespace dlpverify
