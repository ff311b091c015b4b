// `dlpverify plot FILE… -o FIGURE`: redraws figures from results alone, years later, without
// rerunning anything. The kind of figure follows the inputs: converge/check JSON → error against
// Δt (several: an overlay), precision JSON → work-precision diagram, --per-particle CSV → error
// against ξ, --history CSV → error against time. All inputs must be of one kind.
#pragma once

#include <string>
#include <vector>

namespace dlpverify::cli {

struct PlotCommand {
  std::vector<std::string> inputs;
  std::string output;
  std::string title;
  bool relative = false;
  std::vector<std::string> labels;
};

int run_plot_command(const PlotCommand& command);

}  // namespace dlpverify::cli
