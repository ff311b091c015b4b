// Particle-steps per second of the fixed-step integrators on the seed's drag and full cases: the
// whole sphere of docs/model.md §2 (R_out = 100, 4,187,856 particles), default parameters
// (docs/model.md §8).
//
//   build/bench/dlpverify_bench --benchmark_counters_tabular=true
//
// Each iteration copies the launch cloud and advances it by kSteps steps of 0.5 ms (the drag
// case's coarsest level); the copy is timed out of the loop.
#include <benchmark/benchmark.h>

#include <omp.h>

#include "integrators/registry.hpp"
#include "problems/dlp/problem.hpp"

namespace {

using namespace dlpverify;
using namespace dlpverify::dlp;

constexpr long kSteps = 10;

const Cloud& seed_sphere() {
  static const Cloud cloud = make_cloud(Lattice{Shape::sphere, 100, 1, 1e-4}, Launch{100.0}, Parameters{});
  return cloud;
}

void advance_case(benchmark::State& state, const std::string& integrator_name, const char* case_name) {
  const Cloud& launch = seed_sphere();
  const double t0 = initial_time(Lattice{Shape::sphere, 100, 1, 1e-4}, Launch{100.0});
  const DlpProblem problem(find_case(case_name), Parameters{}, launch, t0);
  auto integrator = make_integrator(integrator_name);
  State cloud = launch.state();
  for (auto _ : state) {
    state.PauseTiming();
    cloud = launch.state();
    state.ResumeTiming();
    integrator->advance(problem, cloud, t0, 5e-4, kSteps);
    benchmark::DoNotOptimize(cloud.data());
  }
  const double particle_steps = static_cast<double>(launch.size()) * kSteps;
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(particle_steps, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["particles"] = static_cast<double>(launch.size());
  state.counters["threads"] = omp_get_max_threads();
}

void BM_rk2_drag(benchmark::State& s) { advance_case(s, "rk2", "drag"); }
void BM_euler_drag(benchmark::State& s) { advance_case(s, "euler", "drag"); }
void BM_rk4_drag(benchmark::State& s) { advance_case(s, "rk4", "drag"); }
void BM_rk2_drag_reynolds_law(benchmark::State& s) { advance_case(s, "rk2", "drag-law"); }
void BM_rk2_full(benchmark::State& s) { advance_case(s, "rk2", "full"); }

}  // namespace

BENCHMARK(BM_rk2_drag)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_euler_drag)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_rk4_drag)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_rk2_drag_reynolds_law)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_rk2_full)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
