// How much memory this process can still take, for refusing a study that would not fit before
// anything is allocated (an allocation past it ends in std::bad_alloc mid-study at best, in the
// kernel's OOM killer or a swapping machine at worst).
#pragma once

#include <cstdint>
#include <string>

namespace dlpverify {

struct AvailableMemory {
  std::uint64_t bytes = 0;
  std::string source;  // which limit it is, for the message: "MemAvailable in /proc/meminfo", …
};

// The tightest of: the kernel's MemAvailable (/proc/meminfo; sysconf's free pages where that
// cannot be read), the cgroup v2 limit less its usage (/sys/fs/cgroup/memory.max, a container's),
// and the address-space limit (ulimit -v) less what the process already maps.
AvailableMemory available_memory();

// Bytes as a reader takes them in: "268 MB", "1.88 GB", "2.14 TB" (powers of 1000).
std::string byte_text(double bytes);

}  // namespace dlpverify
