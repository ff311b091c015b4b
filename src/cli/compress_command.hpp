// `dlpverify compress`: the seed's hard-sphere adiabatic compression (docs/model.md §7.2), run
// event-driven over an ensemble of seeds; the table of T2/T1 against V1/V2 beside the laws, the
// quasi-static sweep over wall speeds (--sweep), the engine's events per second (--bench).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace dlpverify::cli {

struct CompressOptions {
  int runs = 20;
  std::uint64_t seed = 1;
  std::vector<double> ratios;          // V1/V2; empty: the seed's seven (half-edges 3.8 … 2.6 m)
  int spheres = 60;
  double radius = 0.02, mass = 1.0, velocity_max = 9.0, edge = 8.0;
  double packing = -1.0;               // > 0: sets the radius (--packing-fraction)
  double wall_speed = 0.2, rest_before = 5.0, rest_after = 3.0;
  int axes = 3;
  double restitution = 1.0, tangential_restitution = -1.0, friction = 0.0;
  bool lattice = false, check_overlaps = false;
  long long max_events = 200000000;    // per run; 0: no limit (events::WorkBound)
  double max_event_rate = 100.0;       // × the kinetic-theory rate; 0: unchecked
  std::vector<double> sweep;           // wall speeds of the quasi-static sweep
  std::vector<int> size_sweep;         // sphere counts of the dense-gas sweep (fixed --packing-fraction)
  std::string expect;                  // seed-table | adiabat | carnahan-starling | law
  double tolerance = 0.01;             // relative
  bool bench = false;
  long bench_events = 1000000;
  std::string json_file, plot_file;
};

// The subcommand, its options bound.
CLI::App* add_compress_command(CLI::App& app, CompressOptions& options);
int run_compress_command(const CompressOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
