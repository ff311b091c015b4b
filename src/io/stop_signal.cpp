#include "io/stop_signal.hpp"

#include <atomic>
#include <mutex>

#include "dlpverify/level_stop.hpp"

namespace dlpverify {

namespace {

volatile std::sig_atomic_t received = 0;

std::mutex instances_mutex;
int instances = 0;  // StopOnSignal objects alive
std::atomic<bool> listening{false};      // instances > 0, for level_stop_requested without the mutex
std::atomic<bool> levels_shared{false};  // under mpirun: a level is ended by every rank together
struct sigaction previous_int {}, previous_term {};

extern "C" void record_signal(int signal) {
  if (received == 0) received = signal;
}

// Installs record_signal for `signal` unless the process was started ignoring it.
void install(int signal, struct sigaction& previous) {
  sigaction(signal, nullptr, &previous);
  if (previous.sa_handler == SIG_IGN) return;
  struct sigaction action {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART | SA_RESETHAND;  // a second signal takes the default action
  sigaction(signal, &action, nullptr);
}

}  // namespace

StopOnSignal::StopOnSignal() {
  const std::lock_guard<std::mutex> lock(instances_mutex);
  if (instances++ > 0) return;
  received = 0;
  install(SIGINT, previous_int);
  install(SIGTERM, previous_term);
  listening = true;
}

StopOnSignal::~StopOnSignal() {
  const std::lock_guard<std::mutex> lock(instances_mutex);
  if (--instances > 0) return;
  listening = false;
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int StopOnSignal::signal() const { return received; }

void StopOnSignal::share_levels() { levels_shared = true; }

bool level_stop_requested() noexcept { return received != 0 && listening && !levels_shared; }

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

}  // namespace dlpverify
