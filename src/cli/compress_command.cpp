#include "cli/compress_command.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include <nlohmann/json.hpp>

#include "problems/spheres/adiabats.hpp"
#include "problems/spheres/compression.hpp"
#include "problems/spheres/compression_report.hpp"
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

CLI::App* add_compress_command(CLI::App& parent, CompressOptions& o) {
  CLI::App& app = *parent.add_subcommand(
      "compress", "Hard-sphere adiabatic compression, event-driven (Harrison's table 1; --axes 1, --sweep, --bench)");
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
  return &app;
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
void say(const std::string& text) { say(text.c_str()); }

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

CompressionExpectation expectation(const std::string& expect) {
  if (expect == "seed-table") return CompressionExpectation::seed_table;
  if (expect == "carnahan-starling") return CompressionExpectation::carnahan_starling;
  if (expect == "law") return CompressionExpectation::law;
  return CompressionExpectation::adiabat;  // check_options refused every other word
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
  say(bench_text(r));
  if (!o.json_file.empty())
    write_output(o.json_file, json_text({{"bench", bench_json(r)}, {"provenance", provenance(command_line)}}, 2) + "\n");
  return kExitDone;
}

int run_speed_sweep(const Compression& c, const CompressOptions& o, const std::vector<double>& ratios,
                    const std::string& command_line) {
  const std::vector<SweepRatio> sweep =
      with_option_names([&] { return sweep_wall_speeds(c, ratios, o.sweep, o.runs, o.seed); });
  say(header_text(c, o.runs, o.seed));
  say("quasi-static limit: |T2/T1 - law(R)| against wall speed (fitted: error > 2 standard errors)\n");
  const SweepReport report = sweep_report(c, sweep, "wall_speed");
  say(report.text);
  write_outputs(o, {{"settings", settings_json(c, o.runs, o.seed)}, {"sweep_parameter", "wall_speed"}, {"sweep", report.rows},
                    {"provenance", provenance(command_line)}});
  return kExitDone;
}

int run_size_sweep(const Compression& c, const CompressOptions& o, const std::vector<double>& ratios,
                   const std::string& command_line) {
  const std::vector<SweepRatio> sweep =
      with_option_names([&] { return sweep_sizes(c, o.packing, ratios, o.size_sweep, o.runs, o.seed); });
  say(header_text(c, o.runs, o.seed));
  say("dense gas at packing fraction %g: |T2/T1 - Carnahan-Starling| against sigma/L as N grows "
      "(fitted: error > 2 standard errors)\n", o.packing);
  const SweepReport report = sweep_report(c, sweep, "sigma/L");
  say(report.text);
  write_outputs(o, {{"settings", settings_json(c, o.runs, o.seed)}, {"sweep_parameter", "sigma_over_edge"}, {"sweep", report.rows},
                    {"provenance", provenance(command_line)}});
  return kExitDone;
}

}  // namespace

int run_compress_command(const CompressOptions& o, const std::string& command_line) {
  check_options(o);
  if (o.bench) return run_bench(o, command_line);
  const Compression c = with_option_names([&] { return to_compression(o); });
  const std::vector<double> ratios = volume_ratios(o.ratios);
  with_option_names([&] { check_inputs(c, ratios, o.seed); });
  // Every run first, then the header and the table: a run that fails (exit 3) leaves stdout empty.
  if (!o.sweep.empty()) return run_speed_sweep(c, o, ratios, command_line);
  if (!o.size_sweep.empty()) return run_size_sweep(c, o, ratios, command_line);

  const std::vector<EnsembleRow> rows = with_option_names([&] { return run_ensemble(c, ratios, o.runs, o.seed); });
  say(header_text(c, o.runs, o.seed));
  say(table_text(c, rows));
  write_outputs(o, {{"settings", settings_json(c, o.runs, o.seed)}, {"rows", rows_json(c, rows)},
                    {"provenance", provenance(command_line)}});
  if (o.expect.empty()) return kExitDone;
  const CompressionVerdict verdict = check_compression(c, rows, expectation(o.expect), o.tolerance);
  say(verdict_text(verdict, o.tolerance));
  return verdict.passed ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
