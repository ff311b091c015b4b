// `dlpverify tableau FILE`: a user's Butcher tableau against its order conditions
// (integrators/tableau/order_conditions.hpp). Prints the row sums c_i = Σ_j a_ij, then every rooted-tree
// condition up to min(6, order + 1) (and the embedded weights' up to min(6, embedded_order + 1)),
// each with its value, residual and verdict, then the orders met beside the orders claimed.
// Exit 0 when the claimed orders are met, 1 naming the first condition they miss, 2 for a bad file.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace dlpverify::cli {

struct TableauOptions {
  std::string file;       // the TOML file (integrators/tableau/tableau_file.hpp)
  std::string json_file;  // --json: every condition and the verdict
  std::string plot_file;  // --plot: the stability region
};

// The `tableau` subcommand of `app`, bound to `options`.
CLI::App* add_tableau_command(CLI::App& app, TableauOptions& options);
int run_tableau_command(const TableauOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
