// `--integrator exec:COMMAND`: a user's program as the integrator under test. Per level the
// initial state and the problem's description go to an HDF5 file (exchange_file.hpp), the program
// runs with the placeholders filled in (command_template.hpp), and its output file's fields become
// the level's final state, compared with the reference like any built-in integrator's.
#pragma once

#include <memory>
#include <string>

#include "dlpverify/integrator.hpp"

namespace dlpverify::exchange {

// The prefix that names an external integrator.
inline constexpr const char* kExecPrefix = "exec:";

struct ExecSettings {
  std::string command;           // the text after "exec:"
  int order = 0;                 // the declared nominal order; 0: not declared
  double timeout_seconds = 3600; // per level
  bool shell = false;            // run through /bin/sh -c
  int threads = 1;               // what {threads} becomes
};

// Refuses settings no program can be run with, before any work: a "declared order" outside
// [0, 20], a "program timeout" outside (0, 1e7] seconds. InputError naming the quantity.
void check_exec_settings(const ExecSettings& settings);

class ExecIntegrator : public Integrator {
 public:
  // Throws ExchangeError for a command that cannot be split (an unclosed quote, nothing at all).
  explicit ExecIntegrator(ExecSettings settings);
  std::string name() const override { return kExecPrefix + settings_.command; }
  int order() const override { return settings_.order; }
  // Throws SolverError with one line (the level, the command, the program's last stderr lines)
  // when the program fails, times out, or leaves an output that is missing or wrong.
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override;
  // Seconds of the last level: writing the input, the program's run, reading the output, and
  // the exchange's overhead (write + read).
  SolverStatistics statistics() const override { return statistics_; }

 private:
  // advance() within its private folder; `signal` gets a signal passed on to the program.
  void run_level(const Problem& problem, State& state, double t0, double dt, long steps, int& signal);
  ExecSettings settings_;
  SolverStatistics statistics_;
};

}  // namespace dlpverify::exchange
