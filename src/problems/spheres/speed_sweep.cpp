#include "problems/spheres/speed_sweep.hpp"

#include <cmath>
#include <functional>

#include "problems/spheres/adiabats.hpp"
#include "problems/spheres/regime.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"

namespace dlpverify::compress {

double law_for(const Compression& c, const EnsembleRow& row) {
  const double r = accessible_ratio(c, row.volume_ratio);
  if (c.axes == 1 && classify(row.collisions_per_sphere_moving) == Regime::collisionless)
    return collisionless_one_axis(r);
  return ideal_adiabat(r);
}

namespace {

void fit_sweep(std::vector<SweepRatio>& result) {
  for (SweepRatio& r : result) {
    std::vector<double> parameters, errors;
    std::vector<int> levels;
    for (std::size_t k = 0; k < r.points.size(); ++k) {
      parameters.push_back(r.points[k].parameter), errors.push_back(r.points[k].error);
      if (r.points[k].resolved) levels.push_back(static_cast<int>(k));
    }
    r.fit = fit_order(parameters, errors, levels);
  }
}

void add_points(std::vector<SweepRatio>& result, const std::vector<EnsembleRow>& rows, double parameter, int spheres,
                int runs, const std::function<double(const EnsembleRow&)>& law) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SweepPoint p{parameter, spheres, rows[i], law(rows[i]), 0.0, false};
    p.error = std::fabs(p.row.mean - p.law);
    p.resolved = runs > 1 && p.error > 2.0 * p.row.stderr_;
    result[i].points.push_back(p);
  }
}

std::vector<SweepRatio> empty_sweep(const std::vector<double>& volume_ratios) {
  std::vector<SweepRatio> result(volume_ratios.size());
  for (std::size_t i = 0; i < volume_ratios.size(); ++i) result[i].volume_ratio = volume_ratios[i];
  return result;
}

}  // namespace

std::vector<SweepRatio> sweep_wall_speeds(Compression c, const std::vector<double>& volume_ratios,
                                          const std::vector<double>& wall_speeds, int runs, std::uint64_t seed) {
  for (double u : wall_speeds)
    if (!(u > 0.0 && std::isfinite(u))) throw InputError("wall speeds", value_text(u), "must be positive and finite");
  std::vector<SweepRatio> result = empty_sweep(volume_ratios);
  for (double u : wall_speeds) {
    c.wall_speed = u;
    add_points(result, run_ensemble(c, volume_ratios, runs, seed), u, c.gas.spheres, runs,
               [&c](const EnsembleRow& row) { return law_for(c, row); });
  }
  fit_sweep(result);
  return result;
}

std::vector<SweepRatio> sweep_sizes(Compression c, double packing, const std::vector<double>& volume_ratios,
                                    const std::vector<int>& spheres, int runs, std::uint64_t seed) {
  if (c.axes != 3) throw InputError("compressed axes", std::to_string(c.axes), "the dense-gas sweep compresses all axes");
  for (int n : spheres)
    if (n < 2 || n > 100000) throw InputError("sphere counts", std::to_string(n), "must lie in [2, 100000]");
  for (double r : volume_ratios) carnahan_starling_adiabat(packing, r);  // throws if η2 ≥ 1
  std::vector<SweepRatio> result = empty_sweep(volume_ratios);
  for (int n : spheres) {
    c.gas.spheres = n;
    c.gas.radius = radius_for_packing(n, packing, c.gas.edge);
    add_points(result, run_ensemble(c, volume_ratios, runs, seed), 2.0 * c.gas.radius / c.gas.edge, n, runs,
               [packing](const EnsembleRow& row) { return carnahan_starling_adiabat(packing, row.volume_ratio); });
  }
  fit_sweep(result);
  return result;
}

}  // namespace dlpverify::compress
