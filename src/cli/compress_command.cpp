#include "cli/compress_command.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include <nlohmann/json.hpp>

#include "problems/spheres/adiabats.hpp"
#include "problems/spheres/compression.hpp"
#include "problems/spheres/event_rate.hpp"
#include "problems/spheres/expectation.hpp"
#include "problems/spheres/regime.hpp"
#include "problems/spheres/seed_table.hpp"
#include "problems/spheres/speed_sweep.hpp"
#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/provenance.hpp"
#include "plot/compression_plots.hpp"
#include "plot/plot.hpp"
#include "io/file_identity.hpp"

namespace dlpverify::cli {

using namespace compress;

void add_compress_options(CLI::App& app, CompressOptions& o) {
  auto option = [&app](const char* name, auto& value, const char* what) {
    return app.add_option(name, value, what)->capture_default_str();
  };
  option("--runs", o.runs, "Runs (random seeds) in each ensemble");
  option("--seed", o.seed, "Random seed of the ensemble: run k uses SplitMix64(seed, k) with std::mt19937_64");
  app.add_option("--ratios", o.ratios, "Volume ratios V1/V2 [default: Harrison's seven, half-edges 3.8 ... 2.6 m]")
      ->delimiter(',');
  option("--spheres", o.spheres, "Number of spheres N");
  option("--radius", o.radius, "Sphere radius R [m]");
  app.add_option("--packing-fraction", o.packing, "Packing fraction N (pi/6) (2R)^3 / V at the start: sets --radius");
  option("--mass", o.mass, "Sphere mass m [kg]");
  option("--velocity-max", o.velocity_max, "Initial velocity components uniform in [-v, v] [m/s]");
  option("--edge", o.edge, "Edge of the cubic box [m]");
  option("--wall-speed", o.wall_speed, "Speed of each moving wall [m/s]");
  option("--rest-before", o.rest_before, "Walls at rest before the motion [s]");
  option("--rest-after", o.rest_after, "Walls at rest after the motion [s]");
  option("--axes", o.axes, "3: all six walls move (Harrison's run); 1: the +x wall alone (one-axis compression)");
  option("--restitution", o.restitution, "Normal restitution e (1: elastic)");
  option("--tangential-restitution", o.tangential_restitution, "Tangential restitution beta0 (-1: none; the full model with --friction > 0)");
  option("--friction", o.friction, "Friction coefficient mu (0: smooth spheres)");
  app.add_flag("--lattice", o.lattice, "Start from a cubic lattice instead of random insertion (dense gases)");
  app.add_flag("--check-overlaps", o.check_overlaps, "Debug: after every event check that no pair overlaps (exit 3 if one does)");
  option("--max-events", o.max_events, "Bound on each run's pair and wall events (exit 3 past it; 0: none)");
  option("--max-event-rate", o.max_event_rate,
         "Bound on events per simulated second, in units of the gas's kinetic-theory rate (exit 3 past it; 0: none)");
  app.add_option("--sweep", o.sweep, "Wall speeds of the quasi-static sweep: error against speed, fitted slope")->delimiter(',');
  app.add_option("--size-sweep", o.size_sweep,
                 "Sphere counts of the dense-gas sweep at fixed --packing-fraction: error against Carnahan-Starling vs sigma/L")
      ->delimiter(',');
  option("--expect", o.expect, "Check (exit 1 on a miss): seed-table (Harrison's table 1), adiabat, carnahan-starling or law (each row's regime law)");
  option("--tolerance", o.tolerance, "Relative tolerance of --expect");
  app.add_flag("--bench", o.bench, "Events per second, N = 108 at packing fraction 0.26 (rho sigma^3 = 0.5), walls at rest");
  option("--bench-events", o.bench_events, "Events measured by --bench (after 10% as many to melt the lattice)");
  app.add_option("--json", o.json_file, "Write the result as JSON");
  app.add_option("--plot", o.plot_file, "The figure (.png, .svg, .pdf): T2/T1 against V1/V2, or error against wall speed");
}

namespace {

// The console table, or nothing when an output (--json -, --plot -) takes standard output.
FILE* console = stdout;
template <class... Args>
void say(const char* format, Args... args) {
  if (!console) return;
  if constexpr (sizeof...(Args) == 0)
    std::fputs(format, console);  // a plain line (clang: a format without arguments is no format)
  else
    std::fprintf(console, format, args...);
}

// The library names quantities (problems/spheres/compression.hpp); this command names its options.
std::string option_for(const std::string& quantity) {
  static const std::pair<const char*, const char*> names[] = {
      {"spheres", "--spheres"},          {"sphere mass", "--mass"},          {"sphere radius", "--radius"},
      {"velocity bound", "--velocity-max"}, {"box edge", "--edge"},          {"wall speed", "--wall-speed"},
      {"rest before", "--rest-before"},  {"rest after", "--rest-after"},     {"compressed axes", "--axes"},
      {"normal restitution", "--restitution"}, {"tangential restitution", "--tangential-restitution"},
      {"friction", "--friction"},        {"volume ratio", "--ratios"},       {"wall speeds", "--sweep"},
      {"packing fraction", "--packing-fraction"}, {"sphere placement", "--radius"}, {"sphere counts", "--size-sweep"}};
  for (const auto& [q, name] : names)
    if (quantity == q) return name;
  return quantity;
}

template <class F>
auto with_option_names(F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    if (e.quantity().empty()) throw;
    throw InputError(option_for(e.quantity()), e.value(), e.reason());
  }
}

void check_options(const CompressOptions& o) {
  auto refuse = [](const char* option, const std::string& value, const char* why) { throw InputError(option, value, why); };
  if (o.runs < 1 || o.runs > 100000) refuse("--runs", std::to_string(o.runs), "must lie in [1, 100000]");
  if (o.bench_events < 1 || o.bench_events > 1000000000L)
    refuse("--bench-events", std::to_string(o.bench_events), "must lie in [1, 1e9]");
  if (!(o.tolerance > 0.0 && o.tolerance < 1.0)) refuse("--tolerance", value_text(o.tolerance), "must lie in (0, 1)");
  if (o.max_events < 0) refuse("--max-events", std::to_string(o.max_events), "must be >= 0 (0: no limit)");
  if (!(o.max_event_rate >= 0.0 && std::isfinite(o.max_event_rate)))
    refuse("--max-event-rate", value_text(o.max_event_rate), "must be >= 0 and finite (0: unchecked)");
  if (!o.expect.empty() && o.expect != "seed-table" && o.expect != "adiabat" && o.expect != "carnahan-starling" &&
      o.expect != "law")
    refuse("--expect", o.expect, "must be seed-table, adiabat, carnahan-starling or law");
  if (o.packing != -1.0 && !(o.packing > 0.0 && o.packing < 0.5))
    refuse("--packing-fraction", value_text(o.packing), "must lie in (0, 0.5)");
  for (double r : o.ratios)
    if (!(r > 1.0 && std::isfinite(r))) refuse("--ratios", value_text(r), "every ratio V1/V2 must exceed 1");
  if (o.sweep.size() == 1) refuse("--sweep", value_text(o.sweep[0]), "needs at least two wall speeds");
  for (double u : o.sweep)
    if (!(u > 0.0 && std::isfinite(u))) refuse("--sweep", value_text(u), "every wall speed must be positive and finite");
  for (int n : o.size_sweep)
    if (n < 2 || n > 100000) refuse("--size-sweep", std::to_string(n), "every sphere count must lie in [2, 100000]");
  if (o.size_sweep.size() == 1) refuse("--size-sweep", std::to_string(o.size_sweep[0]), "needs at least two sphere counts");
  if (!o.size_sweep.empty() && o.packing == -1.0)
    refuse("--size-sweep", std::to_string(o.size_sweep[0]), "needs --packing-fraction (held fixed as N grows)");
  if (!o.size_sweep.empty() && !o.sweep.empty()) refuse("--size-sweep", std::to_string(o.size_sweep[0]), "one sweep at a time: not with --sweep");
  if (o.expect == "seed-table" && (!o.ratios.empty() || o.axes != 3))
    refuse("--expect", o.expect, "compares with Harrison's own ratios, all axes: leave --ratios and --axes unset");
  const bool json_out = !o.json_file.empty() && output_target(o.json_file) == OutputTarget::standard_output;
  const bool plot_out = !o.plot_file.empty() && output_target(o.plot_file) == OutputTarget::standard_output;
  if (json_out && plot_out) refuse("--plot", o.plot_file, "--json already writes to standard output");
  console = json_out || plot_out ? nullptr : stdout;
  refuse_shared_files({}, {{"--json", o.json_file}, {"--plot", o.plot_file}});
  if (!o.json_file.empty()) check_output_path("--json", o.json_file);
  if (!o.plot_file.empty()) check_plot_path("--plot", o.plot_file);
}

Compression to_compression(const CompressOptions& o) {
  Compression c;
  c.gas = {o.spheres, o.mass, o.radius, o.velocity_max, o.edge, o.lattice};
  if (o.packing > 0.0) c.gas.radius = radius_for_packing(o.spheres, o.packing, o.edge);
  c.model = {o.restitution, o.tangential_restitution, o.friction};
  c.wall_speed = o.wall_speed;
  c.rest_before = o.rest_before;
  c.rest_after = o.rest_after;
  c.axes = o.axes;
  c.check_overlaps = o.check_overlaps;
  c.work_bound = {o.max_events, o.max_event_rate};
  validate(c);
  return c;
}

std::vector<double> volume_ratios(const CompressOptions& o) {
  if (!o.ratios.empty()) return o.ratios;
  std::vector<double> ratios;
  for (const SeedRow& row : kSeedTable) ratios.push_back(seed_volume_ratio(row));
  return ratios;
}

void print_header(const Compression& c, const CompressOptions& o) {
  const double volume = c.gas.edge * c.gas.edge * c.gas.edge;
  say("dlpverify compress · %d spheres (m %g kg, R %g m), components uniform in [-%g, %g] m/s · cube %g m\n",
              c.gas.spheres, c.gas.mass, c.gas.radius, c.gas.speed_max, c.gas.speed_max, c.gas.edge);
  say("%s at %g m/s · rest %g s before, %g s after · e %g, beta0 %g, mu %g · %d runs, seed %llu\n",
              c.axes == 3 ? "all six walls move" : "the +x wall moves (one axis)", c.wall_speed, c.rest_before,
              c.rest_after, c.model.restitution, c.model.tangential_restitution, c.model.friction, o.runs,
              static_cast<unsigned long long>(o.seed));
  const double lambda = mean_free_path(c.gas.spheres, c.gas.radius, volume);
  say("packing fraction %.4g at the start · mean free path %.3g m = %.3g box edges (dilute-gas estimate)\n\n",
              initial_packing(c), lambda, lambda / c.gas.edge);
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

// The seed's published simulated T2/T1 at this ratio, or NaN when the ratio is not one of its seven.
double seed_value(double volume_ratio) {
  for (const SeedRow& row : kSeedTable)
    if (std::fabs(volume_ratio / seed_volume_ratio(row) - 1.0) < 1e-9) return row.simulated;
  return std::nan("");
}

void print_table(const Compression& c, const std::vector<EnsembleRow>& rows) {
  const bool all = c.axes == 3;
  say("%7s %9s %9s %9s %9s %10s %8s %9s %8s %8s %9s %9s  %s\n", all ? "V1/V2" : "L1/L2",
              all ? "analytic" : "(r2+2)/3", all ? "CS" : "r^(2/3)", all ? "Harrison" : "", "law(R)", "simulated", "stderr",
              all ? "dev" : "dev(law)", "pair", "wall", "coll/sph", "pair/wall", all ? "regime" : "regime: law");
  for (const EnsembleRow& r : rows) {
    const Regime regime = classify(r.collisions_per_sphere_moving);
    const double law = law_for(c, r), packing2 = initial_packing(c) * r.volume_ratio;
    const double first = all ? ideal_adiabat(r.volume_ratio) : collisionless_one_axis(r.volume_ratio);
    const double second = !all ? ideal_adiabat(r.volume_ratio)
                          : packing2 < 1.0 ? carnahan_starling_adiabat(initial_packing(c), r.volume_ratio)
                                           : std::nan("");
    const std::string seed = all && std::isfinite(seed_value(r.volume_ratio)) ? printf_string("%.2f", seed_value(r.volume_ratio)) : "";
    const bool no_law = !all && regime == Regime::transitional;
    const std::string dev = no_law ? "-" : printf_string("%+.2f%%", 100.0 * (r.mean / (all ? first : law) - 1.0));
    say("%7.3f %9.4f %9.4f %9s %9s %10.4f %8.4f %8s %8.1f %8.1f %9.3g %9.2g  %s%s\n", r.volume_ratio,
                first, second, seed.c_str(), no_law ? "-" : printf_string("%.4f", law).c_str(), r.mean, r.stderr_, dev.c_str(),
                r.pair_events, r.wall_events, r.collisions_per_sphere_moving,
                r.wall_events > 0 ? r.pair_events / r.wall_events : 0.0, to_string(regime).c_str(),
                all ? "" : regime == Regime::collisionless ? ": (r2+2)/3" : regime == Regime::collision_dominated ? ": r^(2/3)" : ": neither");
  }
  say("\n%s · law(R): that law of the compression the centres see, r = prod (L1 - 2R)/(L2 - 2R) · Harrison: "
              "Harrison's table 1, simulated · pair, wall: events per run · coll/sph: pair collisions per sphere while the "
              "walls moved (collisionless <= %g, collision-dominated >= %g)\n",
              all ? "dev: simulated against the analytic (V1/V2)^(2/3) · CS: the Carnahan-Starling adiabat"
                  : "dev(law): simulated against law(R) of the regime",
              kCollisionlessBelow, kCollisionDominatedAbove);
}

CompressionExpectation expectation(const std::string& expect) {
  if (expect == "seed-table") return CompressionExpectation::seed_table;
  if (expect == "carnahan-starling") return CompressionExpectation::carnahan_starling;
  if (expect == "law") return CompressionExpectation::law;
  return CompressionExpectation::adiabat;  // check_options refused every other word
}

// --expect: prints each miss of the library's verdict and the verdict line.
bool rows_pass(const Compression& c, const CompressOptions& o, const std::vector<EnsembleRow>& rows) {
  const CompressionVerdict verdict = check_compression(c, rows, expectation(o.expect), o.tolerance);
  for (const CompressionMiss& m : verdict.misses)
    say("MISS  V1/V2 %.4f: simulated %.4f against %s %.4f (%+.2f%%, tolerance %.2f%%)%s\n", m.volume_ratio, m.simulated,
        verdict.against.c_str(), m.expected, 100.0 * m.deviation, 100.0 * o.tolerance,
        m.transitional ? ", and the regime is transitional: neither law applies" : "");
  say("%s: every ratio within %.2f%% of %s\n", verdict.passed ? "PASS" : "FAIL", 100.0 * o.tolerance,
      verdict.against.c_str());
  return verdict.passed;
}

nlohmann::json settings_json(const Compression& c, const CompressOptions& o) {
  return {{"spheres", c.gas.spheres},     {"radius", c.gas.radius},          {"mass", c.gas.mass},
          {"velocity_max", c.gas.speed_max}, {"edge", c.gas.edge},          {"wall_speed", c.wall_speed},
          {"rest_before", c.rest_before}, {"rest_after", c.rest_after},      {"axes", c.axes},
          {"restitution", c.model.restitution}, {"tangential_restitution", c.model.tangential_restitution},
          {"friction", c.model.friction}, {"runs", o.runs},                   {"seed", o.seed},
          {"lattice", c.gas.lattice},     {"packing_fraction", initial_packing(c)},
          {"max_events", c.work_bound.events}, {"max_event_rate", c.work_bound.rate_factor}};
}

// The figure and the JSON, together or not at all.
void write_outputs(const CompressOptions& o, const nlohmann::json& result) {
  OutputSet outputs;
  if (!o.plot_file.empty()) {
    PlotOptions plot;
    plot.output = o.plot_file;
    plot.option = "--plot";
    outputs.add(o.plot_file, plot_compression(result, plot));
  }
  if (!o.json_file.empty()) outputs.add(o.json_file, json_text(result, 2) + "\n");
  outputs.commit();
}

int run_bench(const CompressOptions& o, const std::string& command_line) {
  const EventRate r = measure_event_rate(108, o.bench_events, o.bench_events / 10, o.seed);
  say("dlpverify compress --bench · N %d hard spheres, packing fraction %.4f (rho sigma^3 = 0.5), walls at rest\n",
              r.spheres, r.packing);
  say("%lld events (%lld pair, %lld wall; %lld stale predictions dropped) in %.3f s wall, %.3f s CPU\n",
              static_cast<long long>(r.events), static_cast<long long>(r.pair_events),
              static_cast<long long>(r.wall_events), static_cast<long long>(r.stale_events), r.wall_seconds,
              r.cpu_seconds);
  say("problems/spheres/s: %.0f (wall clock), %.0f (CPU time) · kinetic energy drift %.2e\n", r.events / r.wall_seconds,
              r.events / r.cpu_seconds, r.energy_drift);
  if (!o.json_file.empty())
    write_output(o.json_file, json_text({{"bench",
                                          {{"spheres", r.spheres}, {"packing_fraction", r.packing}, {"events", r.events},
                                           {"pair_events", r.pair_events}, {"wall_events", r.wall_events},
                                           {"wall_seconds", r.wall_seconds}, {"cpu_seconds", r.cpu_seconds},
                                           {"energy_drift", r.energy_drift}}},
                                         {"provenance", provenance(command_line)}},
                                        2) + "\n");
  return kExitDone;
}

// A sweep's table per ratio, its fitted slope, and the JSON of it all.
nlohmann::json report_sweep(const Compression& c, const std::vector<SweepRatio>& sweep, const char* parameter) {
  nlohmann::json rows = nlohmann::json::array();
  for (const SweepRatio& s : sweep) {
    say("\nV1/V2 %.4f\n%12s %8s %10s %10s %10s %10s %10s  %s\n", s.volume_ratio, parameter, "spheres", "law",
                "simulated", "stderr", "error", "coll/sph", "fitted");
    nlohmann::json points = nlohmann::json::array();
    for (const SweepPoint& p : s.points) {
      say("%12.4g %8d %10.4f %10.4f %10.4f %10.3e %10.3g  %s\n", p.parameter, p.spheres, p.law, p.row.mean,
                  p.row.stderr_, p.error, p.row.collisions_per_sphere_moving, p.resolved ? "yes" : "no (noise)");
      nlohmann::json j = row_json(c, p.row);
      j["parameter"] = p.parameter, j["spheres"] = p.spheres, j["error"] = p.error, j["resolved"] = p.resolved,
      j["law"] = p.law;
      points.push_back(j);
    }
    if (s.fit.valid)
      say("slope of ln error against ln %s: %.3f ± %.3f (95%% CI [%.3f, %.3f]) over %zu points\n", parameter,
                  s.fit.value, s.fit.stderr_, s.fit.ci_low, s.fit.ci_high, s.fit.levels.size());
    else
      say("slope: fewer than two points resolved above the ensemble's noise\n");
    rows.push_back({{"volume_ratio", s.volume_ratio}, {"points", points},
                    {"slope", s.fit.valid ? nlohmann::json(s.fit.value) : nlohmann::json()},
                    {"slope_stderr", number_or_null(s.fit.stderr_)},
                    {"slope_ci", {number_or_null(s.fit.ci_low), number_or_null(s.fit.ci_high)}},
                    {"fitted_points", s.fit.levels}});
  }
  return rows;
}

int run_speed_sweep(const Compression& c, const CompressOptions& o, const std::vector<double>& ratios,
                    const std::string& command_line) {
  const std::vector<SweepRatio> sweep =
      with_option_names([&] { return sweep_wall_speeds(c, ratios, o.sweep, o.runs, o.seed); });
  print_header(c, o);
  say("quasi-static limit: |T2/T1 - law(R)| against wall speed (fitted: error > 2 standard errors)\n");
  const nlohmann::json rows = report_sweep(c, sweep, "wall_speed");
  write_outputs(o, {{"settings", settings_json(c, o)}, {"sweep_parameter", "wall_speed"}, {"sweep", rows},
                    {"provenance", provenance(command_line)}});
  return kExitDone;
}

int run_size_sweep(const Compression& c, const CompressOptions& o, const std::vector<double>& ratios,
                   const std::string& command_line) {
  const std::vector<SweepRatio> sweep =
      with_option_names([&] { return sweep_sizes(c, o.packing, ratios, o.size_sweep, o.runs, o.seed); });
  print_header(c, o);
  say("dense gas at packing fraction %g: |T2/T1 - Carnahan-Starling| against sigma/L as N grows "
              "(fitted: error > 2 standard errors)\n", o.packing);
  const nlohmann::json rows = report_sweep(c, sweep, "sigma/L");
  write_outputs(o, {{"settings", settings_json(c, o)}, {"sweep_parameter", "sigma_over_edge"}, {"sweep", rows},
                    {"provenance", provenance(command_line)}});
  return kExitDone;
}

}  // namespace

int run_compress_command(const CompressOptions& o, const std::string& command_line) {
  check_options(o);
  if (o.bench) return run_bench(o, command_line);
  const Compression c = with_option_names([&] { return to_compression(o); });
  const std::vector<double> ratios = volume_ratios(o);
  with_option_names([&] { check_inputs(c, ratios, o.seed); });
  // Every run first, then the header and the table: a run that fails (exit 3) leaves stdout empty.
  if (!o.sweep.empty()) return run_speed_sweep(c, o, ratios, command_line);
  if (!o.size_sweep.empty()) return run_size_sweep(c, o, ratios, command_line);

  const std::vector<EnsembleRow> rows = with_option_names([&] { return run_ensemble(c, ratios, o.runs, o.seed); });
  print_header(c, o);
  print_table(c, rows);
  nlohmann::json table = nlohmann::json::array();
  for (const EnsembleRow& r : rows) table.push_back(row_json(c, r));
  write_outputs(o, {{"settings", settings_json(c, o)}, {"rows", table}, {"provenance", provenance(command_line)}});
  if (!o.expect.empty() && !rows_pass(c, o, rows)) return kExitCheckFailed;
  return kExitDone;
}

}  // namespace dlpverify::cli
