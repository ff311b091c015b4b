// `dlpverify stagger`: the staggered solution of a backward-Euler step (docs/model.md §7.3).
//   Contraction: one step from the case's initial state at each --dt; the measured contraction per
//   sweep beside the coupled system's spectral radius. A step whose iteration diverges ends the
//   command with exit 3 and the line that says so.
//   --adaptive: the seed's Algorithm 7.1 from --dt to --t-end; the Table 7.1 counts (steps taken,
//   steps rejected, total sweeps), the accepted steps against the convergence limit, and the error
//   at the end against the closed form. Exit 1 when a step at or above the limit was accepted or
//   the error at the end exceeds 10 × --tol.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/options.hpp"

namespace dlpverify::cli {

struct StaggerOptions {
  StaggerOptions() { problem.case_name = "stagger-2x2"; }
  ProblemOptions problem;
  std::vector<double> dt;                // contraction: each step; adaptive: the first step
  std::string sweep;                     // jacobi | gauss-seidel [default: jacobi, adaptive gauss-seidel]
  bool adaptive = false;
  std::optional<double> t_end;           // adaptive [default: the case's]
  double tolerance = 1e-6;               // TOL of every block, and of the local error
  std::vector<std::string> block_tolerances;  // BLOCK=TOL, overriding --tol for one block
  int target_sweeps = 10;                // K_d
  std::optional<double> exponent;        // p [default: the system's, else 1]
  std::optional<double> dt_max;          // Δt_lim
  bool no_error_control = false;         // the document's control alone
  std::string json_file, csv_file, table_file;
};

// The subcommand, its options bound.
CLI::App* add_stagger_command(CLI::App& app, StaggerOptions& options);
int run_stagger_command(StaggerOptions& options, const std::string& command_line);

}  // namespace dlpverify::cli
