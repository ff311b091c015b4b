// Progress of long work on stderr (the CVODE reference, the levels of a study, the runs of a
// compression ensemble or a work-precision sweep): what, how far, the time elapsed and an estimate
// of the time left. On a terminal one line rewritten in place with a carriage return and cleared
// when the work ends; in a CI's log (Mode::log) one whole line per finished item, at most one every
// kLogInterval seconds, which a log keeps as it comes. Off unless the command turns it on (a
// terminal or a CI's log, no --quiet), so a library caller, a pipe, a log file outside a CI and
// every result file never see it.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <vector>

namespace dlpverify::progress {

enum class Mode { off, terminal, log };
// For the whole process; off by default.
void enable(Mode mode);
bool enabled();
Mode mode();
// Whether stderr is a terminal (isatty(2)): where a line rewritten in place can be read.
bool stderr_is_terminal();
// Whether stderr is a CI's log: no terminal, and the environment's CI set (GitHub Actions, GitLab
// CI and most others set CI=true; empty, "false" and "0" say no CI).
bool stderr_is_ci_log();
// A finished item is logged at most this often [s], the first one always.
inline constexpr double kLogInterval = 5.0;

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
  void log(long done);

  std::string what_;
  long total_;
  std::vector<double> weights_;
  bool on_;
  std::atomic<long> done_{0};
  std::chrono::steady_clock::time_point start_, last_shown_;
  bool shown_finished_ = false;  // thread 0 only
  bool logged_ = false;          // thread 0 only: a finished item was logged
};

}  // namespace dlpverify::progress
