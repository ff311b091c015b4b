#include "problems/spheres/event_rate.hpp"

#include <chrono>
#include <cmath>
#include <ctime>

#include "problems/spheres/gas_setup.hpp"
#include "problems/spheres/engine.hpp"

namespace dlpverify::compress {

namespace {

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

EventRate measure_event_rate(int spheres, std::int64_t events, std::int64_t warmup, std::uint64_t seed) {
  GasSetup gas;
  gas.spheres = spheres;
  gas.mass = 1.0;
  gas.radius = 0.5;      // σ = 1
  gas.speed_max = 1.0;
  gas.edge = std::cbrt(spheres / 0.5);  // ρσ³ = 0.5
  gas.lattice = true;
  events::EventEngine engine(place_gas(gas, seed), cube(gas.edge));
  engine.run_events(warmup);
  const events::EventCounts before = engine.counts();
  const double energy = engine.kinetic_energy();
  const auto wall_start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_now();
  engine.run_events(events);
  EventRate r;
  r.cpu_seconds = cpu_now() - cpu_start;
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  r.spheres = spheres;
  r.packing = packing_fraction(spheres, gas.radius, gas.edge * gas.edge * gas.edge);
  r.pair_events = engine.counts().pair - before.pair;
  r.wall_events = engine.counts().wall - before.wall;
  r.stale_events = engine.counts().stale - before.stale;
  r.events = r.pair_events + r.wall_events;
  r.energy_drift = engine.kinetic_energy() / energy - 1.0;
  return r;
}

}  // namespace dlpverify::compress
