#include "problems/spheres/compression_report.hpp"

#include <cmath>

#include "io/format.hpp"
#include "problems/spheres/adiabats.hpp"
#include "problems/spheres/regime.hpp"
#include "problems/spheres/seed_table.hpp"

namespace dlpverify::compress {

namespace {

// The seed's published simulated T2/T1 at this ratio, or NaN when the ratio is not one of its seven.
double seed_value(double volume_ratio) {
  for (const SeedRow& row : kSeedTable)
    if (std::fabs(volume_ratio / seed_volume_ratio(row) - 1.0) < 1e-9) return row.simulated;
  return std::nan("");
}

nlohmann::json row_json(const Compression& c, const EnsembleRow& r) {
  nlohmann::json j{{"volume_ratio", r.volume_ratio},
                   {"analytic", ideal_adiabat(r.volume_ratio)},
                   {"simulated", r.mean},
                   {"stderr", number_or_null(r.stderr_)},
                   {"pair_events", r.pair_events},
                   {"wall_events", r.wall_events},
                   {"pair_events_moving", r.pair_events_moving},
                   {"wall_events_moving", r.wall_events_moving},
                   {"collisions_per_sphere", r.collisions_per_sphere_moving},
                   {"regime", to_string(classify(r.collisions_per_sphere_moving))},
                   {"law", law_for(c, r)},
                   {"accessible_volume_ratio", accessible_ratio(c, r.volume_ratio)},
                   {"runs", r.ratios}};
  const double packing2 = initial_packing(c) * r.volume_ratio;
  if (c.axes == 3 && packing2 < 1.0) j["carnahan_starling"] = carnahan_starling_adiabat(initial_packing(c), r.volume_ratio);
  if (c.axes == 1) j["collisionless"] = collisionless_one_axis(r.volume_ratio);
  return j;
}

}  // namespace

std::vector<double> volume_ratios(const std::vector<double>& given) {
  if (!given.empty()) return given;
  std::vector<double> ratios;
  for (const SeedRow& row : kSeedTable) ratios.push_back(seed_volume_ratio(row));
  return ratios;
}

std::string header_text(const Compression& c, int runs, std::uint64_t seed) {
  std::string text;
  const double volume = c.gas.edge * c.gas.edge * c.gas.edge;
  appendf(text, "dlpverify compress · %d spheres (m %g kg, R %g m), components uniform in [-%g, %g] m/s · cube %g m\n",
          c.gas.spheres, c.gas.mass, c.gas.radius, c.gas.speed_max, c.gas.speed_max, c.gas.edge);
  appendf(text, "%s at %g m/s · rest %g s before, %g s after · e %g, beta0 %g, mu %g · %d runs, seed %llu\n",
          c.axes == 3 ? "all six walls move" : "the +x wall moves (one axis)", c.wall_speed, c.rest_before,
          c.rest_after, c.model.restitution, c.model.tangential_restitution, c.model.friction, runs,
          static_cast<unsigned long long>(seed));
  const double lambda = mean_free_path(c.gas.spheres, c.gas.radius, volume);
  appendf(text, "packing fraction %.4g at the start · mean free path %.3g m = %.3g box edges (dilute-gas estimate)\n\n",
          initial_packing(c), lambda, lambda / c.gas.edge);
  return text;
}

std::string table_text(const Compression& c, const std::vector<EnsembleRow>& rows) {
  std::string text;
  const bool all = c.axes == 3;
  appendf(text, "%7s %9s %9s %9s %9s %10s %8s %9s %8s %8s %9s %9s  %s\n", all ? "V1/V2" : "L1/L2",
          all ? "analytic" : "(r2+2)/3", all ? "CS" : "r^(2/3)", all ? "Harrison" : "", "law(R)", "simulated", "stderr",
          all ? "dev" : "dev(law)", "pair", "wall", "coll/sph", "pair/wall", all ? "regime" : "regime: law");
  for (const EnsembleRow& r : rows) {
    const Regime regime = classify(r.collisions_per_sphere_moving);
    const double law = law_for(c, r), packing2 = initial_packing(c) * r.volume_ratio;
    const double first = all ? ideal_adiabat(r.volume_ratio) : collisionless_one_axis(r.volume_ratio);
    const double second = !all ? ideal_adiabat(r.volume_ratio)
                          : packing2 < 1.0 ? carnahan_starling_adiabat(initial_packing(c), r.volume_ratio)
                                           : std::nan("");
    const std::string seed =
        all && std::isfinite(seed_value(r.volume_ratio)) ? printf_string("%.2f", seed_value(r.volume_ratio)) : "";
    const bool no_law = !all && regime == Regime::transitional;
    const std::string dev = no_law ? "-" : printf_string("%+.2f%%", 100.0 * (r.mean / (all ? first : law) - 1.0));
    appendf(text, "%7.3f %9.4f %9.4f %9s %9s %10.4f %8.4f %8s %8.1f %8.1f %9.3g %9.2g  %s%s\n", r.volume_ratio, first,
            second, seed.c_str(), no_law ? "-" : printf_string("%.4f", law).c_str(), r.mean, r.stderr_, dev.c_str(),
            r.pair_events, r.wall_events, r.collisions_per_sphere_moving,
            r.wall_events > 0 ? r.pair_events / r.wall_events : 0.0, to_string(regime).c_str(),
            all                                      ? ""
            : regime == Regime::collisionless        ? ": (r2+2)/3"
            : regime == Regime::collision_dominated  ? ": r^(2/3)"
                                                     : ": neither");
  }
  appendf(text,
          "\n%s · law(R): that law of the compression the centres see, r = prod (L1 - 2R)/(L2 - 2R) · Harrison: "
          "Harrison's table 1, simulated · pair, wall: events per run · coll/sph: pair collisions per sphere while the "
          "walls moved (collisionless <= %g, collision-dominated >= %g)\n",
          all ? "dev: simulated against the analytic (V1/V2)^(2/3) · CS: the Carnahan-Starling adiabat"
              : "dev(law): simulated against law(R) of the regime",
          kCollisionlessBelow, kCollisionDominatedAbove);
  return text;
}

nlohmann::json rows_json(const Compression& c, const std::vector<EnsembleRow>& rows) {
  nlohmann::json table = nlohmann::json::array();
  for (const EnsembleRow& r : rows) table.push_back(row_json(c, r));
  return table;
}

nlohmann::json settings_json(const Compression& c, int runs, std::uint64_t seed) {
  return {{"spheres", c.gas.spheres},     {"radius", c.gas.radius},          {"mass", c.gas.mass},
          {"velocity_max", c.gas.speed_max}, {"edge", c.gas.edge},          {"wall_speed", c.wall_speed},
          {"rest_before", c.rest_before}, {"rest_after", c.rest_after},      {"axes", c.axes},
          {"restitution", c.model.restitution}, {"tangential_restitution", c.model.tangential_restitution},
          {"friction", c.model.friction}, {"runs", runs},                     {"seed", seed},
          {"lattice", c.gas.lattice},     {"packing_fraction", initial_packing(c)},
          {"max_events", c.work_bound.events}, {"max_event_rate", c.work_bound.rate_factor}};
}

SweepReport sweep_report(const Compression& c, const std::vector<SweepRatio>& sweep, const char* parameter) {
  SweepReport report;
  for (const SweepRatio& s : sweep) {
    appendf(report.text, "\nV1/V2 %.4f\n%12s %8s %10s %10s %10s %10s %10s  %s\n", s.volume_ratio, parameter, "spheres",
            "law", "simulated", "stderr", "error", "coll/sph", "fitted");
    nlohmann::json points = nlohmann::json::array();
    for (const SweepPoint& p : s.points) {
      appendf(report.text, "%12.4g %8d %10.4f %10.4f %10.4f %10.3e %10.3g  %s\n", p.parameter, p.spheres, p.law,
              p.row.mean, p.row.stderr_, p.error, p.row.collisions_per_sphere_moving, p.resolved ? "yes" : "no (noise)");
      nlohmann::json j = row_json(c, p.row);
      j["parameter"] = p.parameter, j["spheres"] = p.spheres, j["error"] = p.error, j["resolved"] = p.resolved,
      j["law"] = p.law;
      points.push_back(j);
    }
    if (s.fit.valid)
      appendf(report.text, "slope of ln error against ln %s: %.3f ± %.3f s.e. (95%% CI [%.3f, %.3f]) over %zu points\n",
              parameter, s.fit.value, s.fit.stderr_, s.fit.ci_low, s.fit.ci_high, s.fit.levels.size());
    else
      appendf(report.text, "slope: fewer than two points resolved above the ensemble's noise\n");
    report.rows.push_back({{"volume_ratio", s.volume_ratio}, {"points", points},
                           {"slope", s.fit.valid ? nlohmann::json(s.fit.value) : nlohmann::json()},
                           {"slope_stderr", number_or_null(s.fit.stderr_)},
                           {"slope_ci", {number_or_null(s.fit.ci_low), number_or_null(s.fit.ci_high)}},
                           {"fitted_points", s.fit.levels}});
  }
  return report;
}

std::string verdict_text(const CompressionVerdict& verdict, double tolerance) {
  std::string text;
  for (const CompressionMiss& m : verdict.misses)
    appendf(text, "MISS  V1/V2 %.4f: simulated %.4f against %s %.4f (%+.2f%%, tolerance %.2f%%)%s\n", m.volume_ratio,
            m.simulated, verdict.against.c_str(), m.expected, 100.0 * m.deviation, 100.0 * tolerance,
            m.transitional ? ", and the regime is transitional: neither law applies" : "");
  appendf(text, "%s: every ratio within %.2f%% of %s\n", verdict.passed ? "PASS" : "FAIL", 100.0 * tolerance,
          verdict.against.c_str());
  return text;
}

std::string bench_text(const EventRate& r) {
  std::string text;
  appendf(text, "dlpverify compress --bench · N %d hard spheres, packing fraction %.4f (rho sigma^3 = 0.5), walls at rest\n",
          r.spheres, r.packing);
  appendf(text, "%lld events (%lld pair, %lld wall; %lld stale predictions dropped) in %.3f s wall, %.3f s CPU\n",
          static_cast<long long>(r.events), static_cast<long long>(r.pair_events), static_cast<long long>(r.wall_events),
          static_cast<long long>(r.stale_events), r.wall_seconds, r.cpu_seconds);
  appendf(text, "events/s: %.0f (wall clock), %.0f (CPU time) · kinetic energy drift %.2e\n",
          r.events / r.wall_seconds, r.events / r.cpu_seconds, r.energy_drift);
  return text;
}

nlohmann::json bench_json(const EventRate& r) {
  return {{"spheres", r.spheres},         {"packing_fraction", r.packing}, {"events", r.events},
          {"pair_events", r.pair_events}, {"wall_events", r.wall_events},  {"wall_seconds", r.wall_seconds},
          {"cpu_seconds", r.cpu_seconds}, {"energy_drift", r.energy_drift}};
}

}  // namespace dlpverify::compress
