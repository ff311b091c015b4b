#include "cli/plot_command.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/printable.hpp"
#include "plot/plot.hpp"
#include "io/input_file.hpp"
#include "io/file_identity.hpp"

namespace dlpverify::cli {

namespace {

const char* describe(ResultKind kind) {
  switch (kind) {
    case ResultKind::convergence: return "a convergence study (JSON)";
    case ResultKind::work_precision: return "a work-precision study (JSON)";
    case ResultKind::per_particle: return "a per-particle error file (CSV)";
    case ResultKind::history: return "an error history (CSV)";
  }
  return "?";
}

ResultFile read_input(const std::string& path) {
  std::ifstream in = open_input_stream("input", path, input_limit::result);
  return read_result(in, path);
}

}  // namespace

ResultFile read_result(std::istream& in, const std::string& path) {
  // A CSV result's header is its first line but for '#' lines (a units line) above it.
  std::string first_line;
  while (std::getline(in, first_line) && first_line.rfind('#', 0) == 0) {
  }
  if (first_line.rfind("particle,xi", 0) == 0) return {ResultKind::per_particle, {}};
  if (first_line.rfind("t,", 0) == 0) return {ResultKind::history, {}};
  in.clear();
  in.seekg(0);
  nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.is_object())
    throw InputError("input", path, "is neither a dlpverify JSON result nor a per-particle or history CSV");
  if (json.contains("runs")) return {ResultKind::work_precision, std::move(json)};
  if (json.contains("levels")) return {ResultKind::convergence, std::move(json)};
  throw InputError("input", path, "is JSON but not a converge, check or precision result");
}

CLI::App* add_plot_command(CLI::App& app, PlotCommand& command) {
  CLI::App* plot = app.add_subcommand(
      "plot", "Redraw a figure from results alone: converge/check JSON (several: overlay), precision JSON, "
              "--per-particle or --history CSV");
  plot->add_option("inputs", command.inputs, "Result files, all of one kind")
      ->required()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  plot->add_option("-o,--output", command.output, "The figure: .png, .svg or .pdf")->required();
  plot->add_option("--title", command.title, "The figure's title [default: built from the results]");
  plot->add_flag("--relative", command.relative, "Error against dt: relative L2 norms on one axis");
  plot->add_option("--labels", command.labels, "Legend names of the CSV inputs, in order")
      ->delimiter(',')
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  return plot;
}

int run_plot_command(const PlotCommand& command) {
  if (command.inputs.empty()) throw InputError("input: give at least one result file");
  std::vector<NamedPath> inputs;
  for (const std::string& input : command.inputs) inputs.push_back({"result", input});
  refuse_shared_files(inputs, {{"-o", command.output}});
  check_plot_path("-o", command.output);
  std::vector<nlohmann::json> results;
  ResultKind kind = ResultKind::convergence;
  for (std::size_t i = 0; i < command.inputs.size(); ++i) {
    ResultFile input = read_input(command.inputs[i]);
    if (i == 0) kind = input.kind;
    if (input.kind != kind)
      throw InputError("input", command.inputs[i],
                       std::string("is ") + describe(input.kind) + ", but " + printable(command.inputs[0]) + " is " +
                           describe(kind));
    results.push_back(std::move(input.json));
  }
  const PlotOptions options{command.output, command.title, "-o", command.relative, command.labels};
  std::string figure;
  switch (kind) {
    case ResultKind::convergence: figure = plot_convergence(results, options); break;
    case ResultKind::work_precision: figure = plot_work_precision(results, options); break;
    case ResultKind::per_particle: figure = plot_error_vs_xi(command.inputs, options); break;
    case ResultKind::history: figure = plot_error_history(command.inputs, options); break;
  }
  write_output(command.output, figure);
  return kExitDone;
}

}  // namespace dlpverify::cli
