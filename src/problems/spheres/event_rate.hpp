// Events per second of the engine on the benchmark of event-driven MD codes: N hard spheres at
// reduced density ρσ³ = 0.5 (packing fraction η = π/6 · 0.5 ≈ 0.26), here in a box with walls at
// rest (DynamO's figure is for periodic boundaries). Measured, never asserted.
#pragma once

#include <cstdint>

namespace dlpverify::compress {

struct EventRate {
  int spheres = 0;
  double packing = 0.0;
  std::int64_t events = 0, pair_events = 0, wall_events = 0, stale_events = 0;
  double wall_seconds = 0.0, cpu_seconds = 0.0;  // cpu: this thread's CPU time (a loaded machine inflates wall time)
  double energy_drift = 0.0;                     // relative change of the kinetic energy over the measured events
};

// Places `spheres` spheres (σ = 1, m = 1, velocity components uniform in [−1, 1]) on a lattice,
// runs `warmup` events to melt it, then measures `events` events.
EventRate measure_event_rate(int spheres, std::int64_t events, std::int64_t warmup, std::uint64_t seed);

}  // namespace dlpverify::compress
