// `dlpverify plot FILE… -o FIGURE`: redraws figures from results alone, years later, without
// rerunning anything. The kind of figure follows the inputs: converge/check JSON → error against
// Δt (several: an overlay), precision JSON → work-precision diagram, --per-particle CSV → error
// against ξ, --history CSV → error against time. All inputs must be of one kind.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace dlpverify::cli {

struct PlotCommand {
  std::vector<std::string> inputs;
  std::string output;
  std::string title;
  bool relative = false;
  std::vector<std::string> labels;
};

// The subcommand, its options bound.
CLI::App* add_plot_command(CLI::App& app, PlotCommand& command);
int run_plot_command(const PlotCommand& command);

enum class ResultKind { convergence, work_precision, per_particle, history };
struct ResultFile {
  ResultKind kind;
  nlohmann::json json;  // for the JSON kinds
};
// What a result is, from its content: JSON with `levels` (converge, check) or `runs` (precision),
// or a CSV whose header starts `particle,xi` (--per-particle) or `t,` (--history); `path` names it.
// Throws InputError for anything else.
ResultFile read_result(std::istream& in, const std::string& path);

}  // namespace dlpverify::cli
