// `dlpverify sharpness --integrator tableau:FILE --case …`: how sharp a verification is, by
// perturbing each coefficient of the tableau alone (integrators/tableau/sharpness.hpp). Prints a
// table of the perturbations and what caught each; --json writes it. Exit 0 when some check
// catches every perturbation, 1 when one escapes them all (or the tableau as written fails its own
// check on the case), 2 bad input.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/options.hpp"

namespace dlpverify::cli {

CLI::App* add_sharpness_command(CLI::App& app, SharpnessOptions& options);
int run_sharpness_command(SharpnessOptions options, const std::string& command_line);

}  // namespace dlpverify::cli
