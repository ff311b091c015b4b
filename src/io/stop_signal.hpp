// SIGINT and SIGTERM as a request to stop where stopping loses nothing (between the levels of a
// study, the level under way abandoned: dlpverify/level_stop.hpp), instead of at once. While a
// StopOnSignal lives, the first such signal is only recorded and its handler reset to the default, so a second one ends the process as usual. A signal the
// process was started ignoring (a background job of a non-interactive shell ignores SIGINT)
// stays ignored. Instances nest, from any thread (a suite's and those of the studies it runs side by
// side): the first to be made installs the handlers and forgets any earlier signal, the last to go
// restores the previous ones, and every one sees the signal recorded meanwhile.
#pragma once

#include <csignal>
#include <string>

namespace dlpverify {

class StopOnSignal {
 public:
  StopOnSignal();   // installs the handlers, unless another instance lives
  ~StopOnSignal();  // restores the previous ones, when no other instance lives
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  int signal() const;  // 0 while none has arrived; else SIGINT or SIGTERM, the first one
  // Under mpirun: a signal ends the study after the level under way, never inside it, for this
  // process's lifetime (a rank abandoning a level alone would leave the others in its sums).
  // Otherwise a signal also abandons the level under way (dlpverify/level_stop.hpp).
  static void share_levels();
};

std::string signal_name(int signal);  // "SIGINT", "SIGTERM", or "signal N"

}  // namespace dlpverify
