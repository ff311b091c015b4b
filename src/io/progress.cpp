#include "io/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>

#include <omp.h>

namespace dlpverify::progress {

namespace {

std::atomic<Mode> g_mode{Mode::off};
// Tasks alive: a task started inside another (the CVODE blocks of one work-precision run) stays
// silent, so the line keeps naming the outer work.
std::atomic<int> g_tasks{0};
// The width of the line on screen, so a shorter one (or the end) overwrites all of it.
std::mutex g_line_mutex;
std::size_t g_line_width = 0;

constexpr double kMinimumInterval = 0.1;  // s: at most ten rewrites a second

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Writes `text` over the current line (an empty text clears it).
void write_line(const std::string& text) {
  const std::lock_guard<std::mutex> lock(g_line_mutex);
  std::string out = "\r" + text;
  if (text.size() < g_line_width) out += std::string(g_line_width - text.size(), ' ');
  if (text.empty()) out += "\r";
  g_line_width = text.size();
  std::fputs(out.c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace

void enable(Mode mode) { g_mode = mode; }
bool enabled() { return g_mode != Mode::off; }
Mode mode() { return g_mode; }
bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }
bool stderr_is_ci_log() {
  const char* ci = std::getenv("CI");
  const std::string value = ci ? ci : "";
  return !stderr_is_terminal() && !value.empty() && value != "false" && value != "0";
}

double seconds_left(double elapsed, long done, long total, const std::vector<double>& weights) {
  if (done <= 0 || total <= 0) return -1.0;
  if (done >= total) return 0.0;
  double finished = 0.0, remaining = 0.0;
  for (long i = 0; i < total; ++i) {
    const double w = static_cast<std::size_t>(i) < weights.size() ? weights[static_cast<std::size_t>(i)] : 1.0;
    (i < done ? finished : remaining) += w;
  }
  return finished > 0.0 ? elapsed * remaining / finished : -1.0;
}

std::string duration_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[48];
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
}

Task::Task(std::string what, long total, std::vector<double> weights)
    : what_(std::move(what)), total_(total), weights_(std::move(weights)),
      on_(g_tasks.fetch_add(1) == 0 && enabled() && total > 0), start_(std::chrono::steady_clock::now()),
      last_shown_(start_) {
  if (on_ && omp_get_thread_num() == 0 && g_mode == Mode::terminal) show(0);
}

Task::~Task() {
  if (on_ && g_mode == Mode::terminal) write_line("");
  g_tasks.fetch_sub(1);
}

void Task::advance(long items) {
  const long done = done_.fetch_add(items, std::memory_order_relaxed) + items;
  if (!on_ || omp_get_thread_num() != 0) return;
  if (g_mode == Mode::log) return log(done);
  const auto now = std::chrono::steady_clock::now();
  if (shown_finished_ && seconds_between(last_shown_, now) < kMinimumInterval) return;
  shown_finished_ = true;
  last_shown_ = now;
  show(done);
}

void Task::show(long done) {
  const double elapsed = seconds_between(start_, std::chrono::steady_clock::now());
  std::string text = "dlpverify: " + what_ + " " + std::to_string(std::min(done + 1, total_)) + "/" +
                     std::to_string(total_) + ", " + duration_text(elapsed) + " elapsed";
  const double left = seconds_left(elapsed, done, total_, weights_);
  if (left >= 0.0) text += ", about " + duration_text(left) + " left";
  write_line(text);
}

void Task::log(long done) {
  const auto now = std::chrono::steady_clock::now();
  if (logged_ && seconds_between(last_shown_, now) < kLogInterval) return;
  logged_ = true;
  last_shown_ = now;
  const double elapsed = seconds_between(start_, now);
  std::string text = "dlpverify: " + what_ + " " + std::to_string(std::min(done, total_)) + "/" + std::to_string(total_) +
                     " finished, " + duration_text(elapsed) + " elapsed";
  const double left = seconds_left(elapsed, done, total_, weights_);
  if (left > 0.0) text += ", about " + duration_text(left) + " left";
  const std::lock_guard<std::mutex> lock(g_line_mutex);
  std::fputs((text + "\n").c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace dlpverify::progress
