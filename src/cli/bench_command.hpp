// `dlpverify bench`: the speed of the integrators' block kernels on a DLP cloud, in particle-steps
// per second — SIMD and scalar right-hand sides, each tableau, one thread and all — beside a
// STREAM-style memory bandwidth for context. Measured, never asserted.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace dlpverify::cli {

struct BenchOptions {
  int outer = 100;         // the seed sphere (4,187,856 particles)
  int threads = 0;         // "all" threads: 0 = OpenMP's default
  double seconds = 0.3;    // the least time each kernel runs
  std::string json_file;
};

// The subcommand, its options bound.
CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench_command(const BenchOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
