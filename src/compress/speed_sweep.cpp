#include "compress/speed_sweep.hpp"

#include <cmath>

#include "compress/adiabats.hpp"
#include "compress/regime.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"

namespace dlpverify::compress {

double law_for(const Compression& c, const EnsembleRow& row) {
  if (c.axes == 1 && classify(row.collisions_per_sphere_moving) == Regime::collisionless)
    return collisionless_one_axis(row.volume_ratio);
  return ideal_adiabat(row.volume_ratio);
}

std::vector<SweepRatio> sweep_wall_speeds(Compression c, const std::vector<double>& volume_ratios,
                                          const std::vector<double>& wall_speeds, int runs, std::uint64_t seed) {
  for (double u : wall_speeds)
    if (!(u > 0.0 && std::isfinite(u))) throw InputError("wall speeds", value_text(u), "must be positive and finite");
  std::vector<SweepRatio> result(volume_ratios.size());
  for (std::size_t i = 0; i < volume_ratios.size(); ++i) result[i].volume_ratio = volume_ratios[i];
  for (double u : wall_speeds) {
    c.wall_speed = u;
    const std::vector<EnsembleRow> rows = run_ensemble(c, volume_ratios, runs, seed);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      SweepPoint p{u, rows[i], law_for(c, rows[i]), 0.0, false};
      p.error = std::fabs(p.row.mean - p.law);
      p.resolved = runs > 1 && p.error > 2.0 * p.row.stderr_;
      result[i].points.push_back(p);
    }
  }
  for (SweepRatio& r : result) {
    std::vector<double> speeds, errors;
    std::vector<int> levels;
    for (std::size_t k = 0; k < r.points.size(); ++k) {
      speeds.push_back(r.points[k].wall_speed), errors.push_back(r.points[k].error);
      if (r.points[k].resolved) levels.push_back(static_cast<int>(k));
    }
    r.fit = fit_order(speeds, errors, levels);
  }
  return result;
}

}  // namespace dlpverify::compress
