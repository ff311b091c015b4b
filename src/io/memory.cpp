#include "io/memory.hpp"

#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

namespace dlpverify {

namespace {

constexpr std::uint64_t kUnknown = std::numeric_limits<std::uint64_t>::max();

// MemAvailable (kB) from /proc/meminfo, else free pages × page size, else unknown.
std::uint64_t system_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line))
    if (line.rfind("MemAvailable:", 0) == 0) {
      std::istringstream fields(line.substr(13));
      std::uint64_t kilobytes = 0;
      if (fields >> kilobytes) return kilobytes * 1024;
    }
  const long pages = ::sysconf(_SC_AVPHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) : kUnknown;
}

// A number from a one-line file, or kUnknown ("max", missing, unreadable).
std::uint64_t number_in(const char* path) {
  std::ifstream in(path);
  std::uint64_t value = 0;
  return in >> value ? value : kUnknown;
}

// cgroup v2: memory.max − memory.current of the process's own group (mounted at /sys/fs/cgroup
// inside a container).
std::uint64_t cgroup_available() {
  const std::uint64_t limit = number_in("/sys/fs/cgroup/memory.max");
  const std::uint64_t used = number_in("/sys/fs/cgroup/memory.current");
  if (limit == kUnknown || used == kUnknown) return kUnknown;
  return limit > used ? limit - used : 0;
}

// What a study maps besides its states under ulimit -v: the allocator's arenas, OpenMP's thread
// stacks, the solvers' workspaces (measured, drag R_out 20: 8.4 MB for CVODE), held back so that an
// allocation SUNDIALS does not check never fails.
constexpr std::uint64_t kAddressSpaceReserve = 16'000'000;

// ulimit -v: RLIMIT_AS less the process's current virtual size (/proc/self/statm, in pages) and
// the reserve.
std::uint64_t address_space_available() {
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnknown;
  const std::uint64_t pages = number_in("/proc/self/statm");
  const long page = ::sysconf(_SC_PAGESIZE);
  const std::uint64_t mapped = pages == kUnknown || page <= 0 ? 0 : pages * static_cast<std::uint64_t>(page);
  return limit.rlim_cur > mapped + kAddressSpaceReserve ? limit.rlim_cur - mapped - kAddressSpaceReserve : 0;
}

}  // namespace

AvailableMemory available_memory() {
  AvailableMemory tightest{kUnknown, "unknown"};
  for (const auto& [bytes, source] : {std::pair{system_available(), "MemAvailable in /proc/meminfo"},
                                      {cgroup_available(), "the cgroup's memory.max less its use"},
                                      {address_space_available(), "ulimit -v less the mapped size"}})
    if (bytes < tightest.bytes) tightest = {bytes, source};
  return tightest;
}

std::string byte_text(double bytes) {
  static const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char text[32];
  std::snprintf(text, sizeof text, u == 0 || bytes >= 100.0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return text;
}

}  // namespace dlpverify
