// Figures (src/plot, issue 5): every kind drawn from small real inputs — convergence studies and a
// work-precision study computed here on a tiny drag cloud (lattice sphere R_out = 3, docs/model.md §4.3
// closed form), CSV files written here — and checked to be real images: the PNG signature and a
// non-trivial size, SVG that parses as XML and names its series, PDF that starts with %PDF.
// Then what must never happen: user text run by gnuplot's shell escapes, a half-written figure,
// a figure under a name that does not say its format.
#include <cmath>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <boost/test/unit_test.hpp>

#include "dlpverify/closed_form.hpp"
#include "problems/dlp/problem.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/history.hpp"
#include "dlpverify/norms.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/work_precision.hpp"
#include "problems/dlp/exact/cloud_solution.hpp"
#include "problems/dlp/exact/drag.hpp"
#include "integrators/sundials/cvode_integrator.hpp"
#include "integrators/registry.hpp"
#include "dlpverify/errors.hpp"
#include "io/process.hpp"
#include "problems/dlp/cloud.hpp"
#include "problems/dlp/rates.hpp"
#include "plot/figure.hpp"
#include "plot/gnuplot_script.hpp"
#include "io/atomic_file.hpp"
#include "plot/plot.hpp"

namespace unit_plot {

using namespace dlpverify;
using namespace dlpverify::dlp;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A folder of its own under the system's temporary folder, removed with everything in it.
struct TemporaryFolder {
  fs::path path;
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "dlpverify-plot-test-XXXXXX").string();
    BOOST_TEST_REQUIRE(::mkdtemp(pattern.data()) != nullptr);
    path = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path)) names.push_back(entry.path().filename().string());
    return names;
  }
};

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

void check_png(const std::string& path, std::size_t min_bytes = 20000) {
  const std::string bytes = read_file(path);
  BOOST_TEST_REQUIRE(bytes.size() > 8u, path << " is empty");
  BOOST_TEST((bytes.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8)), path << " has no PNG signature");
  BOOST_TEST(bytes.size() > min_bytes, path << " holds only " << bytes.size() << " bytes");
}

// Parses as XML (Boost.PropertyTree throws on anything malformed), is an <svg>, and shows every
// one of `labels` as text.
void check_svg(const std::string& path, const std::vector<std::string>& labels) {
  const std::string text = read_file(path);
  BOOST_TEST_REQUIRE(text.size() > 2000u);
  BOOST_TEST((text.rfind("<?xml", 0) == 0 || text.rfind("<svg", 0) == 0));
  BOOST_TEST(text.substr(text.find_last_not_of(" \n\r\t") - 5, 6) == "</svg>");
  std::istringstream in(text);
  boost::property_tree::ptree tree;
  BOOST_CHECK_NO_THROW(boost::property_tree::read_xml(in, tree));
  BOOST_TEST(tree.count("svg") == 1u);
  for (const auto& label : labels) BOOST_TEST(text.find(label) != std::string::npos, path << " does not show \"" << label << "\"");
}

void check_pdf(const std::string& path) {
  const std::string bytes = read_file(path);
  BOOST_TEST(bytes.rfind("%PDF", 0) == 0);
  BOOST_TEST(bytes.size() > 5000u);
}

// The tiny drag cloud: lattice sphere R_out = 3 (Δ = 1e-4 m, u_s = 100 m/s), drag only, constant
// C_D, 0.01 s after t0, measured against its closed form (docs/model.md §4.3).
struct TinyDrag {
  Lattice lattice{Shape::sphere, 3, 1, 1e-4};
  Launch launch{100.0};
  std::unique_ptr<DlpProblem> problem = std::make_unique<DlpProblem>(find_case("drag"), Parameters{}, lattice, launch);
  double t0 = problem->initial_time();
  double t_end = 0.01;
  State initial = problem->initial_state();
  State exact = closed_form(*problem, initial, t_end);
  std::vector<Variable> variables = problem->variables();

  // A converge study of `integrator` at Δt = 5e-4 s / 2^k, k = 0 … 4, as `converge --json` writes it;
  // `measured` names the field groups compared (default: the problem's position and velocity) and
  // `time_unit` is the one the report writes.
  json converge(const std::string& integrator, int order, std::vector<Variable> measured = {},
                const std::string& time_unit = "s") const {
    StudyPlan plan;
    plan.t_end = t_end;
    plan.coarsest_dt = 5e-4;
    plan.ratio = 2.0;
    plan.levels = 5;
    plan.expected_order = order;
    plan.variables = measured.empty() ? variables : measured;
    const StudyResult study = run_study(plan, exact, std::vector<double>(variables.size(), 0.0),
                                        [&](double dt, long steps, SolverStatistics& statistics) {
                                          const auto stepper = make_integrator(integrator);
                                          State state = initial;
                                          stepper->advance(*problem, state, t0, dt, steps);
                                          statistics = stepper->statistics();
                                          return state;
                                        });
    StudyDescription d;
    d.case_name = "drag";
    d.integrator = integrator;
    d.integrator_order = order;
    d.reference = "exact";
    d.particles = static_cast<long long>(initial.rows());
    d.t0 = t0;
    d.time_unit = time_unit;
    return to_json(d, study, std::nullopt);
  }

  // adams and bdf at two tolerances, rk2 at three steps, as `precision --json` writes it.
  json precision() const {
    std::vector<PrecisionRun> runs;
    for (CvodeMethod method : {CvodeMethod::adams, CvodeMethod::bdf})
      for (double rtol : {1e-4, 1e-6, 1e-8}) {
        CvodeSettings settings;
        settings.method = method;
        settings.rtol = rtol;
        settings.atol = absolute_tolerances(*problem, initial, rtol);
        runs.push_back({method == CvodeMethod::adams ? "adams" : "bdf", rtol, std::nullopt, [this, settings](SolverStatistics& statistics) {
                          CvodeIntegrator integrator(settings);
                          State state = initial;
                          integrator.advance(*problem, state, t0, t_end, 1);
                          statistics = integrator.statistics();
                          return state;
                        }});
      }
    for (long steps : {20, 40, 80}) {
      const double dt = t_end / static_cast<double>(steps);
      runs.push_back({"rk2", std::nullopt, dt, [this, dt, steps](SolverStatistics& statistics) {
                        const auto stepper = make_integrator("rk2");
                        State state = initial;
                        stepper->advance(*problem, state, t0, dt, steps);
                        statistics = stepper->statistics();
                        return state;
                      }});
    }
    WorkPrecisionDescription d;
    d.case_name = "drag";
    d.reference = "exact";
    d.particles = static_cast<long long>(initial.rows());
    d.t0 = t0;
    d.t_end = t_end;
    return to_json(d, run_work_precision(runs, exact, {}, variables));
  }
};

const TinyDrag& tiny_drag() {
  static const TinyDrag drag;
  return drag;
}

// A converge result written by hand: position at every status the report knows (ok and fitted,
// round-off, unstable with a NaN and with a blown-up error, an error of exactly 0), and the
// temperature and mass norms of the full case.
json synthetic_study() {
  json levels = json::array();
  const double dts[] = {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5};
  const char* status[] = {"unstable", "unstable", "ok", "ok", "ok", "round-off", "round-off"};
  const double position[] = {std::nan(""), 3e40, 1e-4, 2.5e-5, 6.25e-6, 3e-6, 4e-6};
  for (int k = 0; k < 7; ++k) {
    json l;
    l["level"] = k;
    l["dt"] = dts[k];
    l["l2_position"] = std::isfinite(position[k]) ? json(position[k]) : json();
    l["l2_velocity"] = 0.3 * dts[k] * dts[k];
    l["l2_temperature"] = k < 2 ? json() : json(7.0 * dts[k] * dts[k]);
    l["l2_mass"] = k == 6 ? 0.0 : 1e-9 * dts[k] * dts[k];
    json by = json::object();
    by["position"] = {{"status", status[k]}, {"rule", "by hand"}};
    by["velocity"] = {{"status", "ok"}, {"rule", "by hand"}};
    by["temperature"] = {{"status", k < 2 ? "unstable" : "ok"}, {"rule", "by hand"}};
    by["mass"] = {{"status", k == 6 ? "round-off" : "ok"}, {"rule", "by hand"}};
    l["status_by_variable"] = by;
    levels.push_back(l);
  }
  json fit = {{"value", 2.0}, {"stderr", 0.001}, {"ci95", {1.99, 2.01}}, {"levels_used", {2, 3, 4}}, {"exact_to_round_off", false}};
  json j;
  j["case"] = "full";
  j["integrator"] = "rk2";
  j["integrator_order"] = 2;
  j["particles"] = 924;
  j["levels"] = levels;
  j["fitted_order"] = {{"position", fit},
                       {"velocity", {{"value", 2.0}, {"ci95", nullptr}, {"levels_used", {0, 1}}, {"exact_to_round_off", false}}},
                       {"temperature", fit},
                       {"mass", fit}};
  j["check"] = {{"passed", true}, {"expected_order", 3.0}, {"tolerance", 0.1}, {"findings", json::array()}};
  return j;
}

std::string per_particle_csv(std::size_t particles, bool with_temperature) {
  std::ostringstream out;
  out << "# dlpverify test, per-particle errors at the finest level\n";
  out << "particle,xi,err_position,err_velocity" << (with_temperature ? ",err_temperature" : "") << "\n";
  for (std::size_t p = 0; p < particles; ++p) {
    const double xi = 0.1 + 0.9 * static_cast<double>(p % 997) / 996.0;
    out << p << "," << xi << "," << 1e-7 * xi * (1.0 - 0.9 * xi) + 1e-10 << "," << 2e-4 * xi * xi;
    if (with_temperature) out << "," << (p == 5 ? 0.0 : 3e-4 * xi);
    out << "\n";
  }
  return out.str();
}

std::string history_csv(double scale) {
  std::ostringstream out;
  out << "t,l2_position,l2_velocity,l2_mass\n";
  for (int k = 0; k <= 160; ++k) {
    const double t = 1e-5 + k * 6.25e-5, growth = 1.0 - std::exp(-k / 30.0);
    out << t << "," << scale * 9e-6 * growth << "," << scale * 7e-3 * growth << "," << scale * 1e-14 * growth << "\n";
  }
  return out.str();
}

const std::string kHostileDouble = "x\"; system(\"touch /tmp/pwned\"); print \"";
const std::string kHostileBackquote = "`touch /tmp/pwned2`";
const std::string kHostileSingle = "x'; system('touch /tmp/pwned3'); print '";

void remove_pwned() {
  for (const char* name : {"/tmp/pwned", "/tmp/pwned2", "/tmp/pwned3"}) fs::remove(name);
}

void check_not_pwned(const TemporaryFolder& folder) {
  for (const char* name : {"/tmp/pwned", "/tmp/pwned2", "/tmp/pwned3"})
    BOOST_TEST(!fs::exists(name), name << " exists: gnuplot ran user text");
  for (const auto& file : folder.files())
    BOOST_TEST((file.rfind("pwned", 0) != 0 && file.rfind(".", 0) != 0), "stray file " << file);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(plot)

BOOST_AUTO_TEST_CASE(script_keeps_text_out_of_commands) {
  using dlpverify::plot::GnuplotScript;
  GnuplotScript s;
  const std::string expression = s.text(kHostileDouble);
  BOOST_TEST(expression == "T(1)");
  BOOST_TEST(s.text(kHostileDouble) == "T(1)", "one line per distinct text");
  BOOST_TEST(s.text(kHostileBackquote) == "T(2)");
  // A newline would end the datablock line and an "EOD" line the datablock: both stay data.
  BOOST_TEST(s.text("a\nEOD\nsystem(\"touch /tmp/pwned\")\r\n") == "T(3)");
  BOOST_TEST(GnuplotScript::sanitize("a\nEOD\n") == "a EOD ");
  BOOST_TEST(GnuplotScript::sanitize("bad \xff byte") == "bad \xEF\xBF\xBD byte");
  BOOST_TEST(GnuplotScript::sanitize("Δt ξ ‖e‖₂") == "Δt ξ ‖e‖₂");
  s.command("set title " + expression + " noenhanced");
  const std::string script = s.render();
  std::istringstream lines(script);
  std::string line;
  bool in_text = false;
  int text_lines = 0;
  while (std::getline(lines, line)) {
    if (line == "$TEXT << EOD") {
      in_text = true;
      continue;
    }
    if (in_text && line == "EOD") {
      in_text = false;
      continue;
    }
    if (in_text) {
      BOOST_TEST(line.front() == '>', "every text line starts with '>': " << line);
      ++text_lines;
    } else {
      BOOST_TEST(line.find("system") == std::string::npos, "user text outside the datablock: " << line);
      BOOST_TEST(line.find('`') == std::string::npos, "user text outside the datablock: " << line);
    }
  }
  BOOST_TEST(text_lines == 3);
  for (const char* refused : {"set title \"`touch /tmp/pwned`\"", "set output \"|cat\"", "plot '< ls' using 1:2",
                              "print system(\"id\")", "load \"x.gp\"", "!ls", "set xlabel \"Δt\"", "x = 1 \\",
                              "call \"x\"", "set title @macro", "shell"})
    BOOST_CHECK_THROW(s.command(refused), std::logic_error);
}

BOOST_AUTO_TEST_CASE(processes_run_without_a_shell) {
  // What a child is fed and its arguments reach it as they are: no shell expands ` $ ; |.
  const std::string text = "x`touch /tmp/pwned`; $(id) | cat\n";
  const auto close = [](std::FILE* in) { return std::fclose(in) == 0; };
  const ProcessResult cat = run_process({"cat"}, [&](std::FILE* in) {
    const bool written = std::fputs(text.c_str(), in) >= 0;
    return close(in) && written;
  });
  BOOST_TEST(cat.success);
  BOOST_TEST(cat.output == text);
  BOOST_TEST(run_process({"echo", "$(id)", "`id`"}, close).output == "$(id) `id`\n");
  const ProcessResult failing = run_process({"false"}, close);
  BOOST_TEST(!failing.success);
  BOOST_TEST(failing.ending == "exited with status 1");
  // A child that stops reading costs a failed write, not this process (SIGPIPE).
  const ProcessResult deaf = run_process({"true"}, [&](std::FILE* in) {
    const std::string megabyte(1 << 20, 'x');
    const bool written = std::fwrite(megabyte.data(), 1, megabyte.size(), in) == megabyte.size();
    return close(in) && written;
  });
  BOOST_TEST(!deaf.success);
  BOOST_CHECK_THROW(run_process({"no-such-program-for-dlpverify"}, close), SolverError);
  BOOST_TEST(!fs::exists("/tmp/pwned"));
}

BOOST_AUTO_TEST_CASE(convergence_of_one_study_as_png_svg_and_pdf) {
  TemporaryFolder folder;
  const json rk2 = tiny_drag().converge("rk2", 2);
  PlotOptions o;
  o.output = folder / "rk2.png";
  write_output(o.output, plot_convergence({rk2}, o));
  check_png(o.output);
  o.output = folder / "rk2.svg";
  write_output(o.output, plot_convergence({rk2}, o));
  check_svg(o.output, {"drag · rk2 · ", "position [m]: p = 2.", "velocity [m/s]: p = 2.", "slope 2", "Δt [s]",
                       "L2 error [m, m/s]"});
  o.output = folder / "rk2.pdf";
  write_output(o.output, plot_convergence({rk2}, o));
  check_pdf(o.output);
  o.output = folder / "rk2-relative.svg";
  o.relative_error = true;
  write_output(o.output, plot_convergence({rk2}, o));
  check_svg(o.output, {"relative L2 error", "position: p = 2."});
  BOOST_TEST(folder.files().size() == 4u, "no temporary file is left");
}

BOOST_AUTO_TEST_CASE(convergence_overlay_gives_each_integrator_its_series) {
  TemporaryFolder folder;
  const std::vector<json> studies = {tiny_drag().converge("euler", 1), tiny_drag().converge("rk2", 2),
                                     tiny_drag().converge("rk4", 4)};
  PlotOptions o;
  o.output = folder / "overlay.svg";
  write_output(o.output, plot_convergence(studies, o));
  check_svg(o.output, {"drag · euler, rk2, rk4", "position", "velocity", "euler: p = 1.", "rk2: p = 2.", "rk4: p = 4.",
                       "slope 1", "slope 2", "slope 4", "L2 error [m]", "L2 error [m/s]"});
  o.output = folder / "overlay.png";
  write_output(o.output, plot_convergence(studies, o));
  check_png(o.output);
  // The same integrator twice: told apart by case, then by number.
  o.output = folder / "twice.svg";
  write_output(o.output, plot_convergence({studies[1], studies[1]}, o));
  check_svg(o.output, {"rk2 · drag #1", "rk2 · drag #2"});
}

BOOST_AUTO_TEST_CASE(convergence_marks_level_status_and_the_checked_order) {
  TemporaryFolder folder;
  PlotOptions o;
  o.output = folder / "statuses.svg";
  o.title = "statuses";
  write_output(o.output, plot_convergence({synthetic_study()}, o));
  // Written before results carried units: the units the names imply, Δt in seconds.
  check_svg(o.output, {"statuses", "Δt [s]", "position [m]: p = 2.00 [1.99, 2.01]", "velocity [m/s]: p = 2.00 (2 levels, no interval)",
                       "temperature [K]: p = 2.00 [1.99, 2.01]", "mass [kg]: p = 2.00 [1.99, 2.01]",
                       "round-off: not fitted", "unstable: not fitted", "error exactly 0", "ok: in the fit",
                       "L2 error [m, m/s, K, kg]"});
  const std::string svg = read_file(o.output);
  BOOST_TEST(svg.find("slope 3") != std::string::npos, "check.expected_order (3) sets the slope");
  BOOST_TEST(svg.find("slope 2") == std::string::npos, "not the integrator's order (2)");
  o.output = folder / "statuses.pdf";
  write_output(o.output, plot_convergence({synthetic_study()}, o));
  check_pdf(o.output);
  o.output = folder / "statuses.png";
  write_output(o.output, plot_convergence({synthetic_study()}, o));
  check_png(o.output);
}

// Kuhl & Grote's drag study as the README shows it: position's level 0 pre-asymptotic (out of the
// fit), and a level limited by its reference: each has its own legend entry, and no round-off one.
BOOST_AUTO_TEST_CASE(convergence_legend_names_each_status) {
  TemporaryFolder folder;
  json j = synthetic_study();
  const char* status[] = {"pre-asymptotic", "ok", "ok", "ok", "ok", "reference", "reference"};
  for (int k = 0; k < 7; ++k) {
    j["levels"][k]["l2_position"] = 0.1 * std::pow(0.5, 2 * k);
    j["levels"][k]["status_by_variable"]["position"]["status"] = status[k];
    j["levels"][k]["status_by_variable"]["temperature"]["status"] = "ok";
    j["levels"][k]["l2_temperature"] = 7.0 * std::pow(0.5, 2 * k);
    j["levels"][k]["status_by_variable"]["mass"]["status"] = "ok";
    j["levels"][k]["l2_mass"] = 1e-9 * std::pow(0.5, 2 * k);
  }
  j["fitted_order"]["position"]["levels_used"] = {1, 2, 3, 4};
  PlotOptions o;
  o.output = folder / "pre-asymptotic.svg";
  write_output(o.output, plot_convergence({j}, o));
  check_svg(o.output, {"pre-asymptotic: not fitted", "reference-limited: not fitted", "ok: in the fit"});
  const std::string svg = read_file(o.output);
  BOOST_TEST(svg.find("round-off") == std::string::npos, "no level is round-off, so no round-off entry");
  BOOST_TEST(svg.find("unstable") == std::string::npos, "no level is unstable");
}

BOOST_AUTO_TEST_CASE(work_precision_draws_both_panels) {
  TemporaryFolder folder;
  const json precision = tiny_drag().precision();
  PlotOptions o;
  o.output = folder / "precision.png";
  write_output(o.output, plot_work_precision({precision}, o));
  check_png(o.output);
  o.output = folder / "precision.svg";
  write_output(o.output, plot_work_precision({precision}, o));
  check_svg(o.output, {"drag · work–precision: adams, bdf, rk2", "error against RHS evaluations", "error against wall time",
                       "RHS evaluations", "wall time of the solve [s]", "adams", "bdf", "rk2", "position (solid",
                       "velocity (dashed"});
  // Two results with the same methods: each method is named with its result.
  o.output = folder / "two.svg";
  write_output(o.output, plot_work_precision({precision, precision}, o));
  check_svg(o.output, {"adams · drag #1", "adams · drag #2"});
}

BOOST_AUTO_TEST_CASE(a_second_axis_has_its_own_range) {
  using namespace dlpverify::plot;
  // Errors 1e-7 … 1e-4 on the left, counts 300 … 10 000 on the right: each axis spans its own.
  Panel with{.x_label = "rtol", .y_label = "error", .y2_label = "RHS evaluations"};
  with.elements.push_back(Element{.rows = {{1e-3, 1e-4}, {1e-6, 1e-7}}, .style = "with points"});
  with.elements.push_back(Element{.rows = {{1e-3, 300.0}, {1e-6, 1e4}}, .style = "with points", .y2 = true});
  const std::string script = figure_script(Figure{"t", {with}}).script.render();
  BOOST_TEST(script.find("axes x1y2") != std::string::npos);
  BOOST_TEST(script.find("set logscale y2") != std::string::npos);
  BOOST_TEST(script.find("set ytics nomirror") != std::string::npos);
  const std::size_t at = script.find("set y2range [");
  BOOST_REQUIRE(at != std::string::npos);
  double lo = 0.0, hi = 0.0;
  BOOST_REQUIRE(std::sscanf(script.c_str() + at, "set y2range [%lf:%lf]", &lo, &hi) == 2);
  BOOST_TEST((lo > 100.0 && lo < 300.0 && hi > 1e4 && hi < 1e6), "y2 range [" << lo << ", " << hi << "]");
  // Without an element on it, no second axis is drawn.
  Panel without{.x_label = "rtol", .y_label = "error"};
  without.elements.push_back(with.elements.front());
  const std::string plain = figure_script(Figure{"t", {without}}).script.render();
  BOOST_TEST(plain.find("unset y2tics") != std::string::npos);
  BOOST_TEST(plain.find("x1y2") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(tolerance_figure_draws_work_on_the_error_panel) {
  TemporaryFolder folder;
  // The SDIRK 2(1) sweep of docs/verification.md: errors, RHS evaluations and those for J·v.
  json runs = json::array();
  const double rtol[] = {1e-3, 1e-4, 1e-5, 1e-6}, error[] = {1.046e-4, 1.151e-5, 1.194e-6, 1.222e-7};
  const long rhs[] = {361, 1097, 3373, 10580}, jv[] = {276, 705, 1537, 4534};
  for (int i = 0; i < 4; ++i)
    runs.push_back({{"rtol", rtol[i]}, {"relative_position", error[i]}, {"rhs_evals", rhs[i]}, {"rhs_evals_jacobian", jv[i]}});
  const json study = {{"case", "drag"}, {"integrator", "arkode-adaptive:ARKODE_SDIRK_2_1_2"}, {"variables", {"position"}},
                      {"proportionality", {{"position", {{"exponent", 0.978}}}}}, {"runs", runs}};
  PlotOptions o;
  o.output = folder / "tolerance.svg";
  write_output(o.output, plot_tolerance(study, o));
  check_svg(o.output, {"drag · arkode-adaptive:ARKODE_SDIRK_2_1_2 by tolerance", "RHS evaluations per run",
                       "RHS evaluations (right axis)", "RHS evaluations for J·v (right axis)", "position: E = 0.98",
                       "error = rtol"});
}

BOOST_AUTO_TEST_CASE(error_against_xi_from_per_particle_csv) {
  TemporaryFolder folder;
  write_text(folder / "rk2-particles.csv", per_particle_csv(800, true));
  write_text(folder / "rk4-particles.csv", per_particle_csv(800, false));
  PlotOptions o;
  o.output = folder / "xi.png";
  write_output(o.output, plot_error_vs_xi({folder / "rk2-particles.csv"}, o));
  check_png(o.output);
  o.output = folder / "xi.svg";
  write_output(o.output, plot_error_vs_xi({folder / "rk2-particles.csv"}, o));
  check_svg(o.output, {"rk2-particles", "position [m]", "velocity [m/s]", "temperature [K]", "ξ",
                       "1 error of exactly 0 on the bottom edge"});
  o.output = folder / "xi-overlay.svg";
  o.labels = {"rk2", "rk4"};
  write_output(o.output, plot_error_vs_xi({folder / "rk2-particles.csv", folder / "rk4-particles.csv"}, o));
  check_svg(o.output, {"rk2", "rk4", "position", "velocity", "temperature"});
}

BOOST_AUTO_TEST_CASE(error_against_xi_thins_a_large_cloud) {
  TemporaryFolder folder;
  write_text(folder / "big.csv", per_particle_csv(45000, false));
  PlotOptions o;
  o.output = folder / "big.svg";
  write_output(o.output, plot_error_vs_xi({folder / "big.csv"}, o));
  check_svg(o.output, {"of 45\u202F000 particles drawn (every 2nd, and each ξ bin's extremes)"});
}

BOOST_AUTO_TEST_CASE(error_history_from_csv) {
  TemporaryFolder folder;
  write_text(folder / "rk2-history.csv", history_csv(1.0));
  write_text(folder / "rk4-history.csv", history_csv(1e-3));
  PlotOptions o;
  o.output = folder / "history.png";
  write_output(o.output, plot_error_history({folder / "rk2-history.csv"}, o));
  check_png(o.output);
  o.output = folder / "history.svg";
  write_output(o.output, plot_error_history({folder / "rk2-history.csv"}, o));
  check_svg(o.output, {"L2 error against time at the finest level · rk2-history", "position [m]", "velocity [m/s]",
                       "mass [kg]", "t [s]"});
  o.output = folder / "history-overlay.pdf";
  write_output(o.output, plot_error_history({folder / "rk2-history.csv", folder / "rk4-history.csv"}, o));
  check_pdf(o.output);
  // A gas study's history (docs/model.md §7.1): temperature and pressure, each with its unit.
  write_text(folder / "gas-history.csv",
             "t,l2_temperature,l2_pressure,ref_l2_temperature,ref_l2_pressure\n1e-5,1e-6,4e-4,6012,2.03e6\n"
             "2e-5,5e-6,1.7e-3,6018,2.04e6\n");
  o.output = folder / "gas-history.svg";
  write_output(o.output, plot_error_history({folder / "gas-history.csv"}, o));
  check_svg(o.output, {"temperature [K]", "pressure [Pa]"});
}

// A problem of its own (issue 24): its variables and units as the files declare them, in the
// files' order, and a dimensionless step. "energy" and "angle" are the drag cloud's position and
// velocity columns under other names and units; what is drawn is only what the files say.
const std::vector<Variable> kOwnVariables = {{"energy", 0, 3, "J"}, {"angle", 3, 3, "rad"}};

BOOST_AUTO_TEST_CASE(reports_write_each_variable_s_unit_and_the_unit_of_time) {
  const json study = tiny_drag().converge("rk2", 2, kOwnVariables, "1");
  BOOST_TEST(study["variables"] == json({"energy", "angle"}));
  BOOST_TEST(study["units"] == json({{"energy", "J"}, {"angle", "rad"}}));
  BOOST_TEST(study["time_unit"] == "1");
  const json drag = tiny_drag().converge("rk2", 2);
  BOOST_TEST(drag["units"] == json({{"position", "m"}, {"velocity", "m/s"}}));  // docs/model.md §5
  BOOST_TEST(drag["time_unit"] == "s");
  // The history: a units line (t's unit, then each column's) only when a unit is not the one the
  // name implies; the cloud's file starts with its header as it always did.
  const std::vector<HistoryPoint> history = {{0.5, {1e-6, 2e-6}, {1.0, 2.0}}};
  BOOST_TEST(format_history(history, kOwnVariables, "1") ==
             "# units: 1,J,rad,J,rad\nt,l2_energy,l2_angle,ref_l2_energy,ref_l2_angle\n0.5,9.9999999999999995e-07,"
             "1.9999999999999999e-06,1,2\n");
  BOOST_TEST(format_history(history, tiny_drag().variables, "s").rfind(
                 "t,l2_position,l2_velocity,ref_l2_position,ref_l2_velocity\n", 0) == 0);
  BOOST_TEST(format_history(history, tiny_drag().variables, "1").rfind("# units: 1,m,m/s,m,m/s\n", 0) == 0);
  // The per-particle errors: one member off by 3 in its energy and 4 in its angle (scalars here).
  StudyResult one;
  one.plan.variables = {{"energy", 0, 1, "J"}, {"angle", 1, 1, "rad"}};
  one.finest = State::Constant(1, 2, 0.0);
  one.finest << 3.0, 4.0;
  const State zero = State::Zero(1, 2);
  BOOST_TEST(format_per_particle(one, zero, Eigen::ArrayXd::Constant(1, 0.5)) ==
             "# units: 1,1,J,rad\nparticle,xi,err_energy,err_angle\n0,0.5,3,4\n");
  one.plan.variables = {{"position", 0, 1, "m"}, {"velocity", 1, 1, "m/s"}};
  BOOST_TEST(format_per_particle(one, zero, Eigen::ArrayXd::Constant(1, 0.5)) ==
             "particle,xi,err_position,err_velocity\n0,0.5,3,4\n");
}

BOOST_AUTO_TEST_CASE(convergence_draws_the_variables_and_step_its_result_declares) {
  TemporaryFolder folder;
  PlotOptions o;
  o.output = folder / "own.svg";
  write_output(o.output, plot_convergence({tiny_drag().converge("rk2", 2, kOwnVariables, "1")}, o));
  // In the result's order: energy, then angle (not the alphabetical order of its JSON keys).
  check_svg(o.output, {"energy [J]: p = 2.", "angle [rad]: p = 2.", "L2 error [J, rad]", "<text>Δt</text>"});
  BOOST_TEST(read_file(o.output).find("[s]") == std::string::npos, "a dimensionless step has no unit");
  // Overlaid with the cloud's study: a panel per variable, each with its own unit.
  o.output = folder / "overlay.svg";
  write_output(o.output, plot_convergence({tiny_drag().converge("rk2", 2), tiny_drag().converge("rk4", 4, kOwnVariables, "1")}, o));
  check_svg(o.output, {"L2 error [m]", "L2 error [m/s]", "L2 error [J]", "L2 error [rad]", "Δt [s]", "<text>Δt</text>"});
  // The same variables with a step in seconds and a dimensionless one: a panel for each unit of
  // time, never one axis labelled with one of them for both.
  o.output = folder / "two-units.svg";
  write_output(o.output, plot_convergence({tiny_drag().converge("rk2", 2), tiny_drag().converge("rk4", 4, {}, "1")}, o));
  check_svg(o.output, {"position [m] · Δt [s]", "position [m] · Δt<", "velocity [m/s] · Δt [s]", "velocity [m/s] · Δt<"});
}

// analyze without a reference measures y_k − y_{k+1} (its JSON's reference is "next run"): the axis
// says differences, not errors; overlaid with a study against a reference, it says both.
BOOST_AUTO_TEST_CASE(convergence_of_self_differences_says_so_on_its_axis) {
  TemporaryFolder folder;
  PlotOptions o;
  json differences = tiny_drag().converge("rk2", 2);
  differences["reference"] = "next run";
  o.output = folder / "self.svg";
  write_output(o.output, plot_convergence({differences}, o));
  check_svg(o.output, {"L2 difference of successive runs [m, m/s]"});
  BOOST_TEST(read_file(o.output).find("L2 error") == std::string::npos);
  o.output = folder / "mixed.svg";
  write_output(o.output, plot_convergence({differences, tiny_drag().converge("rk4", 4)}, o));
  check_svg(o.output, {"L2 error or difference of successive runs [m]"});
}

BOOST_AUTO_TEST_CASE(history_draws_the_variables_and_units_its_file_declares) {
  TemporaryFolder folder;
  std::vector<HistoryPoint> history;
  for (int k = 1; k <= 20; ++k) history.push_back({0.05 * k, {1e-6 * k, 3e-7 * k}, {1.0, 2.0}});
  write_text(folder / "pendulum-history.csv", format_history(history, kOwnVariables, "1"));
  PlotOptions o;
  o.output = folder / "history.svg";
  write_output(o.output, plot_error_history({folder / "pendulum-history.csv"}, o));
  check_svg(o.output, {"energy [J]", "angle [rad]", "L2 error [J, rad]", "<text>t</text>"});
  BOOST_TEST(read_file(o.output).find("[s]") == std::string::npos, "dimensionless time has no unit");
  // The per-particle errors of the same problem.
  write_text(folder / "pendulum-particles.csv", "# units: 1,1,rad\nparticle,xi,err_angle\n0,0.5,1e-6\n1,1,2e-6\n");
  o.output = folder / "xi.svg";
  write_output(o.output, plot_error_vs_xi({folder / "pendulum-particles.csv"}, o));
  check_svg(o.output, {"angle [rad]", "error of the particle ‖yₚ − yₚ(t)‖ [rad]"});
}

BOOST_AUTO_TEST_CASE(work_precision_draws_every_variable_its_result_declares) {
  json runs = json::array();
  for (int k = 0; k < 3; ++k)
    runs.push_back({{"method", "rk4"}, {"dt", 0.1 / (1 << k)}, {"rhs_evals", 40 << k}, {"steps", 10 << k},
                    {"wall_s", 1e-3 * (1 << k)}, {"rel_l2_energy", 1e-4 / (16 << (4 * k))},
                    {"rel_l2_angle", 1e-5 / (16 << (4 * k))}, {"rel_l2_momentum", 1e-6 / (16 << (4 * k))}});
  const json result = {{"case", "pendulum"}, {"variables", {"energy", "angle", "momentum"}},
                       {"units", {{"energy", "J"}, {"angle", "rad"}, {"momentum", "kg m/s"}}},
                       {"time_unit", "1"}, {"runs", runs}};
  TemporaryFolder folder;
  PlotOptions o;
  o.output = folder / "precision.svg";
  write_output(o.output, plot_work_precision({result}, o));
  check_svg(o.output, {"pendulum · work–precision: rk4", "energy (solid, ●)", "angle (dashed, ○)", "momentum (dotted, ■)"});
}

BOOST_AUTO_TEST_CASE(malformed_input_is_an_input_error_and_writes_nothing) {
  TemporaryFolder folder;
  PlotOptions o;
  o.output = folder / "figure.png";
  write_text(folder / "header.csv", "xi,particle,err_position\n0,1,2\n");
  write_text(folder / "unknown.csv", "particle,xi,err_position,charge\n0,1,2,3\n");
  write_text(folder / "twice.csv", "particle,xi,err_angle,err_angle\n0,1,2,3\n");
  write_text(folder / "no-variable.csv", "particle,xi\n0,1\n");
  write_text(folder / "units.csv", "# units: 1,1\nparticle,xi,err_angle\n0,1,2\n");
  write_text(folder / "short.csv", "t,l2_position,l2_velocity\n0,1\n");
  write_text(folder / "word.csv", "t,l2_position,l2_velocity\n0,1,two\n");
  write_text(folder / "no-error.csv", "t,ref_l2_position\n0,1\n");
  BOOST_CHECK_THROW(plot_error_vs_xi({folder / "header.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_vs_xi({folder / "unknown.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_vs_xi({folder / "twice.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_vs_xi({folder / "no-variable.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_vs_xi({folder / "units.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_vs_xi({folder / "missing.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_history({folder / "short.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_history({folder / "word.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_error_history({folder / "no-error.csv"}, o), InputError);
  BOOST_CHECK_THROW(plot_convergence({}, o), InputError);
  BOOST_CHECK_THROW(plot_convergence({json{{"runs", json::array()}}}, o), InputError);
  BOOST_CHECK_THROW(plot_work_precision({synthetic_study()}, o), InputError);
  BOOST_TEST(!fs::exists(o.output));
  BOOST_TEST(folder.files().size() == 8u, "only the eight CSV files");
}

BOOST_AUTO_TEST_CASE(unknown_extension_throws_and_writes_nothing) {
  TemporaryFolder folder;
  const json study = synthetic_study();
  for (const std::string name : {"figure.jpg", "figure", "figure.png.txt", "figure.eps"}) {
    PlotOptions o;
    o.output = folder / name;
    o.option = "-o";
    try {
      write_output(o.output, plot_convergence({study}, o));
      BOOST_ERROR(name << " was accepted");
    } catch (const InputError& e) {
      BOOST_TEST(std::string(e.what()).rfind("-o = ", 0) == 0, e.what());
    }
    BOOST_CHECK_THROW(check_plot_path("--plot", o.output), InputError);
  }
  BOOST_CHECK_THROW(check_plot_path("--plot", folder.path.string()), InputError);  // a folder
  BOOST_CHECK_NO_THROW(check_plot_path("--plot", folder / "ok.PDF"));
  BOOST_TEST(folder.files().empty());
}

BOOST_AUTO_TEST_CASE(hostile_text_is_drawn_never_run) {
  remove_pwned();
  TemporaryFolder folder;
  for (const std::string& hostile : {kHostileDouble, kHostileBackquote, kHostileSingle}) {
    json study = synthetic_study();
    study["case"] = hostile;
    study["integrator"] = hostile;
    PlotOptions o;
    o.title = hostile;
    o.output = folder / "plain.png";
    write_output(o.output, plot_convergence({study}, o));
    check_png(o.output);
    o.output = folder / "plain.svg";
    write_output(o.output, plot_convergence({study, study}, o));
    check_svg(o.output, {});

    json precision = {{"case", hostile}, {"particles", 3}, {"runs", json::array()}};
    for (int k = 0; k < 3; ++k)
      precision["runs"].push_back({{"method", hostile}, {"rhs_evals", 10 << k}, {"wall_s", 1e-3 * (k + 1)},
                                   {"rel_l2_position", 1e-3 / (1 << (2 * k))}, {"rel_l2_velocity", 1e-2 / (1 << (2 * k))}});
    o.output = folder / "precision.png";
    write_output(o.output, plot_work_precision({precision}, o));
    check_png(o.output, 10000);

    // Text from file names and labels, and the output's own name.
    write_text(folder / "errors.csv", per_particle_csv(50, false));
    o.labels = {hostile};
    o.output = folder / "xi.png";
    write_output(o.output, plot_error_vs_xi({folder / "errors.csv"}, o));
    check_png(o.output, 10000);
    write_text(folder / "history.csv", history_csv(1.0));
    o.output = folder / "history.png";
    write_output(o.output, plot_error_history({folder / "history.csv"}, o));
    check_png(o.output, 10000);
    check_not_pwned(folder);
  }
  // File names cannot hold '/', so these would touch files in the output's folder (gnuplot's
  // working folder) or in /tmp.
  const std::vector<std::string> names = {"x\"; system(\"touch pwned4\"); print \".png", "`touch pwned5`.png",
                                          "x'; system('touch pwned6'); print '.png", "$(touch pwned7).svg",
                                          "a|touch pwned8.pdf"};
  for (const auto& name : names) {
    write_text(folder / "input `touch pwned9`.csv", history_csv(1.0));
    PlotOptions o;
    o.output = folder / name;
    write_output(o.output, plot_error_history({folder / "input `touch pwned9`.csv"}, o));
    BOOST_TEST(fs::file_size(o.output) > 5000u);
  }
  check_not_pwned(folder);
}

BOOST_AUTO_TEST_CASE(gnuplot_failure_is_a_solver_error_and_leaves_the_old_figure) {
  TemporaryFolder folder;
  const std::string target = folder / "figure.png";
  write_text(target, "the old figure");
  dlpverify::plot::GnuplotScript broken;
  broken.command("plot $NO_SUCH_DATABLOCK using 1:2 notitle");
  try {
    dlpverify::plot::render_figure(broken, 800, 600, target, "--plot");
    BOOST_ERROR("a failing gnuplot script was accepted");
  } catch (const SolverError& e) {
    const std::string message = e.what();
    BOOST_TEST_MESSAGE(message);
    BOOST_TEST(message.find('\n') == std::string::npos, "one line: " << message);
    BOOST_TEST(message.find("gnuplot failed") != std::string::npos);
  }
  BOOST_TEST(read_file(target) == "the old figure");
  BOOST_TEST(folder.files().size() == 1u, "no temporary file is left");
  // A good figure replaces it whole.
  PlotOptions o;
  o.output = target;
  write_output(o.output, plot_convergence({synthetic_study()}, o));
  check_png(target);
  BOOST_TEST(folder.files().size() == 1u);
  // A figure into a folder that does not exist is bad input, and no folder is made.
  o.output = folder / "new/sub/figure.pdf";
  BOOST_CHECK_THROW(write_output(o.output, plot_convergence({synthetic_study()}, o)), InputError);
  BOOST_TEST(!std::filesystem::exists(folder / "new"));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_plot
