// One updating line on stderr while long work runs (the CVODE reference, the levels of a study,
// the runs of a compression ensemble or a work-precision sweep): what, how far, the time elapsed
// and an estimate of the time left, rewritten in place with a carriage return and cleared when
// the work ends. Off unless the command turns it on (stderr a terminal, no --quiet), so a library
// caller, a pipe, a log file and every result file never see it.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <vector>

namespace dlpverify::progress {

// On for the whole process, or off (the default).
void enable(bool on);
bool enabled();
// Whether stderr is a terminal (isatty(2)): where a line rewritten in place can be read.
bool stderr_is_terminal();

// The time left after `done` of the items' weights w_i were finished in `elapsed` seconds,
// at the pace so far: elapsed · Σ_{i≥done} w_i / Σ_{i<done} w_i (equal weights when none given).
// Negative when nothing is finished yet (no pace to go by).
double seconds_left(double elapsed, long done, long total, const std::vector<double>& weights);
// "7 s", "2 min 05 s", "1 h 03 min".
std::string duration_text(double seconds);

// One piece of long work: `total` items called `what` ("level", "reference block", "run").
// advance() may be called from any OpenMP thread: the count is atomic, and only thread 0 of a
// team (or the thread outside any parallel region) writes the line, at most ten times a second;
// the first finished item is always shown, so even a short run shows an estimate once. A task
// started while another is alive shows nothing: the line names the outermost work.
class Task {
 public:
  // weights: the relative cost of each item (say the steps of each level), for the time left.
  Task(std::string what, long total, std::vector<double> weights = {});
  ~Task();  // clears the line
  Task(const Task&) = delete;
  Task& operator=(const Task&) = delete;

  void advance(long items = 1);

 private:
  void show(long done);

  std::string what_;
  long total_;
  std::vector<double> weights_;
  bool on_;
  std::atomic<long> done_{0};
  std::chrono::steady_clock::time_point start_, last_shown_;
  bool shown_finished_ = false;  // thread 0 only
};

}  // namespace dlpverify::progress
