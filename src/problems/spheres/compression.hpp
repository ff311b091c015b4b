// One compression run and its ensemble (docs/model.md §7.2, the seed's experiment): the walls
// rest, move inward at constant speed until the volume has shrunk by the ratio V1/V2, then rest
// again; T2/T1 is the ratio of the spheres' mean translational kinetic energy after and before.
#pragma once

#include <cstdint>
#include <vector>

#include "problems/spheres/gas_setup.hpp"
#include "problems/spheres/collision_rule.hpp"
#include "problems/spheres/engine.hpp"

namespace dlpverify::compress {

struct Compression {
  GasSetup gas;
  events::CollisionModel model;
  double wall_speed = 0.2;    // m/s, every moving wall
  double rest_before = 5.0;   // s, walls at rest before the motion
  double rest_after = 3.0;    // s, after it
  int axes = 3;               // 3: all six walls move (the seed); 1: the +x wall alone
  bool check_overlaps = false;
  // Each run's bound on its work (events::WorkBound): past 2e8 events, or events coming faster than
  // 100 × the kinetic-theory rate, it fails with SolverError.
  events::WorkBound work_bound{200000000, 100.0};
};

// Throws InputError naming the quantity at fault.
void validate(const Compression& c);

// Throws InputError unless every ratio exceeds 1 and leaves room for a sphere, and the first
// run's spheres fit in the box: bad input found before any run starts.
void check_inputs(const Compression& c, const std::vector<double>& volume_ratios, std::uint64_t seed);

// How far each moving wall travels to reach the volume ratio, and for how long.
double wall_travel(const Compression& c, double volume_ratio);
double motion_time(const Compression& c, double volume_ratio);

// The compression of the space the sphere centres can reach, Π_k (L1k − 2R)/(L2k − 2R): hard
// walls keep every centre R away from them, so a gas of finite spheres is compressed a little
// more than the box (docs/model.md §7.2: the seed's own excess over (V1/V2)^(2/3) is this).
double accessible_ratio(const Compression& c, double volume_ratio);

struct RunResult {
  double t1 = 0.0, t2 = 0.0;  // mean translational kinetic energy per sphere before and after [J]
  double ratio = 0.0;         // T2/T1
  std::int64_t pair_events = 0, wall_events = 0;
  std::int64_t pair_events_moving = 0, wall_events_moving = 0;  // while the walls moved
};
RunResult run_compression(const Compression& c, double volume_ratio, std::uint64_t seed);

// The ensemble at one ratio: runs with seeds run_seed(seed, 0 … runs−1) (the same initial gases
// at every ratio), their mean, standard error and mean event counts.
struct EnsembleRow {
  double volume_ratio = 0.0;
  double mean = 0.0, stderr_ = 0.0;
  double pair_events = 0.0, wall_events = 0.0;  // per run
  double pair_events_moving = 0.0, wall_events_moving = 0.0;
  double collisions_per_sphere_moving = 0.0;    // 2 × pair events while the walls moved / N
  std::vector<double> ratios;                   // every run's T2/T1
};
// Every (ratio, run) pair, on OpenMP threads; the result does not depend on the thread count.
std::vector<EnsembleRow> run_ensemble(const Compression& c, const std::vector<double>& volume_ratios, int runs,
                                      std::uint64_t seed);

}  // namespace dlpverify::compress
