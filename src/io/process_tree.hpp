// Ending every process a program started, wherever it went.
//
// A process group or a session does not hold them all: a descendant may call setpgid or setsid
// and leave both. What holds them is ancestry, and a descendant whose parent ends would be handed
// to init and lost. So while a DescendantReaper lives this process is a child subreaper
// (prctl PR_SET_CHILD_SUBREAPER): an orphaned descendant becomes our child instead, and the
// descendants still below a living parent are found by their parents in /proc. Linux only.
#pragma once

#include <sys/types.h>

#include <utility>
#include <vector>

namespace dlpverify {

class DescendantReaper {
 public:
  // Makes this process a child subreaper and notes the children it already has: those, and
  // what they start, are not ours to end.
  DescendantReaper();
  // Ends what is left (end_all), then restores the subreaper setting it found.
  ~DescendantReaper();
  DescendantReaper(const DescendantReaper&) = delete;
  DescendantReaper& operator=(const DescendantReaper&) = delete;

  // Kills (SIGKILL) every child of this process that is not one of the noted ones, and every
  // descendant of those, reaps them, and returns once none is left: orphans that come to us while
  // it works are ended too. A process is signalled through a pidfd opened while /proc still
  // shows it, so a pid reused meanwhile by a stranger is never hit. One reaper at a time per
  // process: two in different threads would end each other's programs.
  void end_all();

 private:
  std::vector<std::pair<pid_t, unsigned long long>> kept_;  // (pid, start time) of the children found
  int previous_ = 0;                                        // the subreaper setting found
};

}  // namespace dlpverify
