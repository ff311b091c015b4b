// Events per second of the hard-sphere engine (src/problems/spheres, docs/model.md §7.2) on the standard
// benchmark of event-driven MD: N spheres at ρσ³ = 0.5 (packing fraction 0.26), here between walls
// at rest. DynamO reports ≈ 89,000 collisions/s for N = 108 (periodic) on this kind of machine.
//
//   build/bench/dlpverify_bench_events --benchmark_counters_tabular=true
//
// The gas is placed on a lattice and melted by 10⁵ events outside the timing; each iteration then
// runs 10⁵ events. Measured, never asserted.
#include <benchmark/benchmark.h>

#include <cmath>

#include "problems/spheres/gas_setup.hpp"
#include "problems/spheres/engine.hpp"

namespace {

using namespace dlpverify;

void hard_spheres(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  compress::GasSetup gas;
  gas.spheres = n, gas.radius = 0.5, gas.speed_max = 1.0, gas.lattice = true;
  gas.edge = std::cbrt(n / 0.5);
  events::EventEngine engine(compress::place_gas(gas, 1), compress::cube(gas.edge));
  engine.run_events(100000);
  constexpr std::int64_t kEvents = 100000;
  for (auto _ : state) engine.run_events(kEvents);
  state.counters["events/s"] = benchmark::Counter(static_cast<double>(kEvents) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["N"] = n;
}

}  // namespace

BENCHMARK(hard_spheres)->Arg(108)->Arg(256)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
