#include "problems/spheres/compression.hpp"

#include <cmath>
#include <exception>

#include "dlpverify/errors.hpp"
#include "problems/spheres/engine.hpp"
#include "io/format.hpp"
#include "io/progress.hpp"

namespace dlpverify::compress {

namespace {

void require(bool ok, const char* quantity, double value, const char* reason) {
  if (!ok) throw InputError(quantity, value_text(value), reason);
}

}  // namespace

void validate(const Compression& c) {
  require(c.gas.edge > 0.0 && std::isfinite(c.gas.edge), "box edge", c.gas.edge, "must be positive and finite");
  require(c.gas.spheres >= 1 && c.gas.spheres <= 100000, "spheres", c.gas.spheres, "must lie in [1, 100000]");
  require(c.gas.mass > 0.0 && std::isfinite(c.gas.mass), "sphere mass", c.gas.mass, "must be positive and finite");
  require(c.gas.radius > 0.0 && c.gas.radius < 0.5 * c.gas.edge, "sphere radius", c.gas.radius,
          "must be positive and less than half the box edge");
  require(c.gas.speed_max > 0.0 && std::isfinite(c.gas.speed_max), "velocity bound", c.gas.speed_max,
          "must be positive and finite");
  require(c.wall_speed > 0.0 && std::isfinite(c.wall_speed), "wall speed", c.wall_speed, "must be positive and finite");
  require(c.rest_before >= 0.0 && std::isfinite(c.rest_before), "rest before", c.rest_before, "must be ≥ 0 and finite");
  require(c.rest_after >= 0.0 && std::isfinite(c.rest_after), "rest after", c.rest_after, "must be ≥ 0 and finite");
  require(c.axes == 1 || c.axes == 3, "compressed axes", c.axes, "must be 1 or 3");
  require(c.model.restitution >= 0.0 && c.model.restitution <= 1.0, "normal restitution", c.model.restitution,
          "must lie in [0, 1]");
  require(c.model.tangential_restitution >= -1.0 && c.model.tangential_restitution <= 1.0, "tangential restitution",
          c.model.tangential_restitution, "must lie in [-1, 1]");
  require(c.model.friction >= 0.0 && std::isfinite(c.model.friction), "friction", c.model.friction,
          "must be ≥ 0 and finite");
}

// All axes: each of the six walls moves (L1 − L2)/2 with L2 = L1 r^(−1/3); one axis: the +x wall
// moves L1 − L2 with L2 = L1 / r.
double wall_travel(const Compression& c, double volume_ratio) {
  const double edge = c.gas.edge;
  return c.axes == 3 ? 0.5 * (edge - edge / std::cbrt(volume_ratio)) : edge - edge / volume_ratio;
}

double motion_time(const Compression& c, double volume_ratio) { return wall_travel(c, volume_ratio) / c.wall_speed; }

double accessible_ratio(const Compression& c, double volume_ratio) {
  const double d = 2.0 * c.gas.radius, l1 = c.gas.edge;
  if (c.axes == 3) return std::pow((l1 - d) / (l1 / std::cbrt(volume_ratio) - d), 3);
  return (l1 - d) / (l1 / volume_ratio - d);
}

namespace {

// The compressed box must hold the spheres as a fluid: its shortest edge at least two diameters,
// and the packing fraction η1 V1/V2 below 0.5 (hard spheres freeze near 0.49 and jam near 0.64;
// a run pressed towards jamming has ever more events in ever less time).
void check_ratio(const Compression& c, double volume_ratio) {
  if (!(volume_ratio > 1.0 && std::isfinite(volume_ratio)))
    throw InputError("volume ratio", value_text(volume_ratio), "must exceed 1");
  const double travel = wall_travel(c, volume_ratio);
  const double edge2 = c.gas.edge - (c.axes == 3 ? 2.0 : 1.0) * travel;
  const double packing2 = packing_fraction(c.gas.spheres, c.gas.radius, c.gas.edge * c.gas.edge * c.gas.edge) * volume_ratio;
  if (!(edge2 >= 4.0 * c.gas.radius) || !(packing2 < 0.5))
    throw InputError("volume ratio", value_text(volume_ratio),
                     "the compressed box must stay a fluid: packing fraction below 0.5 (here " + value_text(packing2) +
                         ") and every edge at least two diameters");
}

}  // namespace

void check_inputs(const Compression& c, const std::vector<double>& volume_ratios, std::uint64_t seed) {
  validate(c);
  for (double ratio : volume_ratios) check_ratio(c, ratio);
  place_gas(c.gas, run_seed(seed, 0));
}

RunResult run_compression(const Compression& c, double volume_ratio, std::uint64_t seed) {
  check_ratio(c, volume_ratio);
  const double travel = wall_travel(c, volume_ratio);
  events::EventEngine engine(place_gas(c.gas, seed), cube(c.gas.edge), c.model);
  engine.check_overlaps(c.check_overlaps);
  engine.bound_work(c.work_bound);
  RunResult r;
  const double n = c.gas.spheres;
  r.t1 = engine.kinetic_energy() / n;

  engine.run_until(c.rest_before);
  const events::EventCounts before = engine.counts();
  const double u = c.wall_speed;
  if (c.axes == 3)
    engine.set_wall_speeds({u, u, u}, {-u, -u, -u});
  else
    engine.set_wall_speeds({0.0, 0.0, 0.0}, {-u, 0.0, 0.0});
  engine.run_until(c.rest_before + travel / u);
  const events::EventCounts moved = engine.counts();
  engine.set_wall_speeds({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0});
  engine.run_until(c.rest_before + travel / u + c.rest_after);

  r.t2 = engine.kinetic_energy() / n;
  r.ratio = r.t2 / r.t1;
  r.pair_events = engine.counts().pair;
  r.wall_events = engine.counts().wall;
  r.pair_events_moving = moved.pair - before.pair;
  r.wall_events_moving = moved.wall - before.wall;
  return r;
}

std::vector<EnsembleRow> run_ensemble(const Compression& c, const std::vector<double>& volume_ratios, int runs,
                                      std::uint64_t seed) {
  const int rows = static_cast<int>(volume_ratios.size());
  std::vector<RunResult> results(static_cast<std::size_t>(rows) * runs);
  check_inputs(c, volume_ratios, seed);
  // The first failure (in job order, so the same one whatever the threads) is rethrown as it was.
  std::vector<std::exception_ptr> failures(results.size());
  progress::Task task("compression run", static_cast<long>(results.size()));
#pragma omp parallel for schedule(dynamic)
  for (int job = 0; job < rows * runs; ++job) {
    try {
      results[job] = run_compression(c, volume_ratios[job / runs], run_seed(seed, job % runs));
    } catch (const SolverError& e) {  // which run failed: its ratio and its index in the ensemble
      failures[job] = std::make_exception_ptr(
          SolverError(printf_string("V1/V2 %.6g, run %d: %s", volume_ratios[job / runs], job % runs, e.what())));
    } catch (...) {
      failures[job] = std::current_exception();
    }
    task.advance();
  }
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);

  std::vector<EnsembleRow> table;
  for (int i = 0; i < rows; ++i) {
    EnsembleRow row;
    row.volume_ratio = volume_ratios[i];
    double sum = 0.0;
    for (int k = 0; k < runs; ++k) {
      const RunResult& r = results[static_cast<std::size_t>(i) * runs + k];
      row.ratios.push_back(r.ratio);
      sum += r.ratio;
      row.pair_events += r.pair_events, row.wall_events += r.wall_events;
      row.pair_events_moving += r.pair_events_moving, row.wall_events_moving += r.wall_events_moving;
    }
    row.mean = sum / runs;
    double squares = 0.0;
    for (double x : row.ratios) squares += (x - row.mean) * (x - row.mean);
    row.stderr_ = runs > 1 ? std::sqrt(squares / (runs - 1) / runs) : std::nan("");
    row.pair_events /= runs, row.wall_events /= runs, row.pair_events_moving /= runs, row.wall_events_moving /= runs;
    row.collisions_per_sphere_moving = 2.0 * row.pair_events_moving / c.gas.spheres;
    table.push_back(row);
  }
  return table;
}

}  // namespace dlpverify::compress
