#include "cli/bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <nlohmann/json.hpp>
#include <omp.h>

#include "families/families.hpp"
#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "problems/dlp/problem.hpp"
#include "simd/vector_math.hpp"
#include "integrators/registry.hpp"

namespace dlpverify::cli {

using namespace dlp;  // the DLP cloud's types

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// STREAM's triad a = b + s c over three arrays far larger than the caches, best of three [GB/s].
double triad_bandwidth() {
  const std::size_t n = std::size_t{1} << 24;  // 3 × 128 MB
  std::vector<double> a(n), b(n, 1.0), c(n, 2.0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) a[i] = 0.0;  // first touch by the threads that use it
  double best = 0.0;
  for (int repeat = 0; repeat < 3; ++repeat) {
    const auto start = Clock::now();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
    best = std::max(best, 3.0 * sizeof(double) * static_cast<double>(n) / seconds_since(start) / 1e9);
  }
  return best;
}

struct Kernel {
  std::string case_name, integrator;
  int threads;
  DlpProblem::RhsPath path;
  double particle_steps_per_s = 0.0;
};

// Particle-steps per second of one integrator on one cloud, net of a run's fixed cost. A run
// copies the cloud into the threads' blocks, steps each block in L1 and copies it back; a study
// level of hundreds of steps hardly sees that copy, a run of a few steps is mostly copy (RK2 on
// drag: one step costs a quarter of the copy). So rates come from differences of run times: runs
// of 1 and 9 steps size S, then runs of S and 3S steps, filling `seconds`, give the rate of 2S
// steps. (Where one step alone takes a quarter of `seconds`, S is 1 without the sizing runs.)
// Where noise leaves the difference under half the long run's time (a fixed cost no run has),
// the long run's own rate is reported: never a rate the runs do not show.
double measure(DlpProblem& problem, const State& initial, const std::string& integrator_name, double seconds) {
  const auto integrator = make_integrator(integrator_name);
  const double dt = 1e-6, t0 = problem.initial_time();
  const auto time_steps = [&](long steps) {
    State state = initial;
    const auto start = Clock::now();
    integrator->advance(problem, state, t0, dt, steps);
    return std::max(seconds_since(start), 1e-9);
  };
  long steps = 1;
  if (const double one = time_steps(1); one < seconds / 4.0) {
    const double nine = time_steps(9);
    const double per_step = nine > one ? (nine - one) / 8.0 : nine / 9.0;
    steps = std::max(1L, static_cast<long>(seconds / (4.0 * per_step)));
  }
  const double short_run = time_steps(steps), long_run = time_steps(3 * steps);
  const double particles = static_cast<double>(initial.rows());
  if (long_run - short_run < 0.5 * long_run) return particles * static_cast<double>(3 * steps) / long_run;
  return particles * static_cast<double>(2 * steps) / (long_run - short_run);
}

}  // namespace

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options) {
  CLI::App* bench = app.add_subcommand(
      "bench", "Speed of the block kernels in particle-steps/s: SIMD and scalar right-hand sides, each tableau, "
               "1 and all threads, beside the memory bandwidth (measured, never asserted)");
  bench->add_option("--outer", options.outer, "Cloud radius in lattice spacings (100: Kuhl & Grote's sphere, 4,187,856 particles)")->capture_default_str();
  bench->add_option("--threads", options.threads, "Threads of the 'all threads' runs (0: all cores)")->capture_default_str();
  bench->add_option("--seconds", options.seconds, "Least time each kernel runs [s]")->capture_default_str();
  bench->add_option("--json", options.json_file, "Write the figures as JSON");
  return bench;
}

int run_bench_command(const BenchOptions& options, const std::string& command_line) {
  if (options.outer < 1 || options.outer > 400) throw InputError("--outer", std::to_string(options.outer), "must lie in [1, 400]");
  if (options.threads < 0 || options.threads > 4 * omp_get_num_procs())
    throw InputError("--threads", std::to_string(options.threads), "must lie in [0, 4 x the cores]");
  if (!(options.seconds > 0.0 && options.seconds <= 60.0))
    throw InputError("--seconds", std::to_string(options.seconds), "must lie in (0, 60]");
  if (!options.json_file.empty()) check_output_path("--json", options.json_file);

  const int all = options.threads > 0 ? options.threads : omp_get_max_threads();
  const double bandwidth = triad_bandwidth();
  std::printf("dlpverify bench · ISA %s (%d doubles per vector) · triad bandwidth %.1f GB/s · %d thread(s) max\n",
              simd::isa(), simd::lanes(), bandwidth, all);
  std::printf("%-6s %-6s %7s %16s %16s %8s\n", "case", "method", "threads", "simd [M/s]", "scalar [M/s]", "speed-up");

  std::vector<Kernel> kernels;
  long particles = 0;
  for (const char* case_name : {"drag", "full"}) {
    ProblemOptions o;
    o.case_name = case_name;
    o.outer = options.outer;
    fill_case_defaults(o);
    const std::unique_ptr<DlpProblem> owned = make_dlp_problem(o);
    DlpProblem& problem = *owned;
    const State initial = problem.initial_state();
    particles = initial.rows();
    for (const char* integrator : {"euler", "heun", "rk2", "rk4"})
      for (int threads : all > 1 ? std::vector<int>{1, all} : std::vector<int>{1}) {
        omp_set_num_threads(threads);
        double rate[2];
        for (auto path : {DlpProblem::RhsPath::simd, DlpProblem::RhsPath::scalar}) {
          problem.set_rhs_path(path);
          rate[path == DlpProblem::RhsPath::scalar] = measure(problem, initial, integrator, options.seconds);
          kernels.push_back({case_name, integrator, threads, path, rate[path == DlpProblem::RhsPath::scalar]});
        }
        std::printf("%-6s %-6s %7d %16.1f %16.1f %7.2fx\n", case_name, integrator, threads, rate[0] / 1e6, rate[1] / 1e6,
                    rate[0] / rate[1]);
        std::fflush(stdout);
      }
    problem.set_rhs_path(DlpProblem::RhsPath::simd);
  }
  omp_set_num_threads(all);

  if (!options.json_file.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (const Kernel& k : kernels)
      rows.push_back({{"case", k.case_name}, {"integrator", k.integrator}, {"threads", k.threads},
                      {"path", k.path == DlpProblem::RhsPath::simd ? "simd" : "scalar"}, {"particles", particles},
                      {"particle_steps_per_s", k.particle_steps_per_s}});
    const nlohmann::json result{{"isa", simd::isa()}, {"lanes", simd::lanes()}, {"bandwidth_gbs", bandwidth},
                                {"kernels", rows}, {"provenance", provenance(command_line)}};
    write_output(options.json_file, json_text(result, 2) + "\n");
  }
  return kExitDone;
}

}  // namespace dlpverify::cli
