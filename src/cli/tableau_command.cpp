#include "cli/tableau_command.hpp"

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"
#include "integrators/tableau/stability.hpp"
#include "integrators/tableau/tableau_file.hpp"
#include "integrators/tableau/tableau_report.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/output_path.hpp"
#include "io/provenance.hpp"
#include "plot/gnuplot_script.hpp"
#include "plot/stability_plot.hpp"
#include "io/file_identity.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

namespace {

// The stability region's window, Re z and Im z in [−10, 10] (an explicit method's region lies
// within |z| < 7 up to order 8; an A-stable one's covers the left half), and its grid.
constexpr double kRegionHalfWidth = 10.0;
constexpr int kRegionPoints = 401;

}  // namespace

CLI::App* add_tableau_command(CLI::App& app, TableauOptions& options) {
  CLI::App* command = app.add_subcommand(
      "tableau", "Check a Butcher tableau file (TOML) against its row sums and order conditions up to order 6 "
                 "(exit 0 its claimed order is met, 1 not)");
  command->add_option("file", options.file, "The tableau: name, order, c, b, A [, b_embedded, embedded_order]")->required();
  command->add_option("--json", options.json_file, "Write every condition and the verdict as JSON");
  command->add_option("--plot", options.plot_file,
                      "Draw the stability region {z : |R(z)| <= 1} over Re z, Im z in [-10, 10] (.png, .svg or .pdf)");
  return command;
}

int run_tableau_command(const TableauOptions& options, const std::string& command_line) {
  // Both on standard output would interleave the JSON and the figure's bytes.
  if (!options.json_file.empty() && !options.plot_file.empty() &&
      output_target(options.json_file) == OutputTarget::standard_output &&
      output_target(options.plot_file) == OutputTarget::standard_output)
    throw InputError("--plot", options.plot_file, "--json already writes to standard output");
  refuse_shared_files({{"tableau file", options.file}}, {{"--json", options.json_file}, {"--plot", options.plot_file}});
  if (!options.json_file.empty()) check_output_path("--json", options.json_file);
  if (!options.plot_file.empty()) {
    check_output_path("--plot", options.plot_file);
    plot::figure_format("--plot", options.plot_file);
  }
  const bool json_on_stdout = !options.json_file.empty() && output_target(options.json_file) == OutputTarget::standard_output;
  const bool plot_on_stdout = !options.plot_file.empty() && output_target(options.plot_file) == OutputTarget::standard_output;
  const RuntimeTableau tableau = read_tableau_file(options.file);
  const TableauVerdict verdict = judge_tableau(tableau);
  // Every output is made before any replaces its old file (a failure leaves them all as they were).
  OutputSet outputs;
  if (!options.json_file.empty()) {
    nlohmann::json j = verdict.report;
    j["provenance"] = provenance(command_line);
    outputs.add(options.json_file, json_text(j, 2) + "\n");
  }
  if (!options.plot_file.empty())
    outputs.add(options.plot_file,
                plot::stability_region_figure(stability_grid(tableau, kRegionHalfWidth, kRegionPoints),
                                              "tableau " + tableau.name, options.plot_file, "--plot"));
  outputs.commit();
  if (!json_on_stdout && !plot_on_stdout) std::fputs(console_text(verdict.table).c_str(), stdout);  // after the outputs: nothing printed if one fails
  std::fflush(stdout);
  return verdict.passed ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
