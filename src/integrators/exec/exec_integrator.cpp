#include "integrators/exec/exec_integrator.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <utility>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "exchange/command_runner.hpp"
#include "exchange/command_template.hpp"
#include "io/printable.hpp"
#include "exchange/exchange_file.hpp"

namespace dlpverify::exchange {

namespace {

// A private folder (mkdtemp, mode 0700) under $TMPDIR or /tmp, removed with what is in it.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/dlpverify-exec-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr)
      throw SolverError("exec: cannot make a temporary folder " + pattern + ": " + std::strerror(errno));
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void check_exec_settings(const ExecSettings& settings) {
  if (settings.order < 0 || settings.order > 20)
    throw InputError("declared order", std::to_string(settings.order), "must lie in [0, 20]");
  if (!std::isfinite(settings.timeout_seconds) || settings.timeout_seconds <= 0.0 || settings.timeout_seconds > 1e7)
    throw InputError("program timeout", value_text(settings.timeout_seconds), "must lie in (0, 1e7] seconds");
}

ExecIntegrator::ExecIntegrator(ExecSettings settings) : settings_(std::move(settings)) {
  check_exec_settings(settings_);
  command_argv(settings_.command, settings_.shell, {});  // refuses an unclosed quote now, not at the first level
}

// A SIGINT, SIGTERM or SIGHUP that came while the program ran was passed on to it; once the
// level's folder is removed it is raised again here, to end dlpverify as it would have.
void ExecIntegrator::advance(const Problem& problem, State& state, double t0, double dt, long steps) {
  check_step(dt, steps);
  statistics_ = SolverStatistics{};
  statistics_.steps = 0;
  if (steps == 0) return;  // no level to run: the program is not started
  int signal = 0;
  try {
    run_level(problem, state, t0, dt, steps, signal);
  } catch (...) {
    if (signal != 0) std::raise(signal);
    throw;
  }
  if (signal != 0) std::raise(signal);
}

void ExecIntegrator::run_level(const Problem& problem, State& state, double t0, double dt, long steps, int& signal) {
  const StepPlan plan{t0, dt, steps, settings_.threads};
  const std::string level = "exec: level dt = " + exact_text(dt) + " s (" + std::to_string(steps) + " steps)";
  const std::string command = "command '" + printable(settings_.command, 100) + "'";
  const TemporaryFolder folder;
  const std::string input = folder.file("input.h5"), output = folder.file("output.h5");

  auto start = std::chrono::steady_clock::now();
  try {
    write_exchange_file(input, problem, state, plan);
  } catch (const ExchangeError& e) {
    throw SolverError(level + ": " + e.what());
  }
  const double write_seconds = seconds_since(start);

  const std::map<std::string, std::string> values{
      {"input", input}, {"output", output}, {"dt", exact_text(dt)}, {"steps", std::to_string(steps)},
      {"t0", exact_text(t0)}, {"t_end", exact_text(plan.t_end())}, {"threads", std::to_string(settings_.threads)}};
  CommandResult run;
  try {
    run = run_command(command_argv(settings_.command, settings_.shell, values), settings_.timeout_seconds);
  } catch (const ExchangeError& e) {
    throw SolverError(level + ": " + command + ": " + e.what());
  }
  signal = run.signal;
  const std::string said = run.last_lines.empty() ? "its stderr is empty" : "its stderr ends: " + run.last_lines;
  if (!run.success) throw SolverError(level + ": " + command + " " + run.ending + "; " + said);

  start = std::chrono::steady_clock::now();
  try {
    read_exchange_fields(output, problem, state);
  } catch (const ExchangeError& e) {
    throw SolverError(level + ": " + command + " succeeded but " + e.what() + "; " + said);
  }
  const double read_seconds = seconds_since(start);
  statistics_.steps = steps;
  statistics_.extras = {{"exchange_write_seconds", write_seconds},
                        {"exchange_read_seconds", read_seconds},
                        {"exchange_overhead_seconds", write_seconds + read_seconds},
                        {"command_seconds", run.seconds}};
}

}  // namespace dlpverify::exchange
