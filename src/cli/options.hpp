// Every option of `dlpverify converge`, `check` and `precision`, with its documented default.
// CLI11 binds this one struct, and a study file (--config) holds the same keys, so a flag and a
// file never disagree. Options left unset take the case's defaults (t-end, dt, levels).
//
// Each subcommand gets only the options that mean something to it (no silently ignored flags):
//   converge   cloud, physics, study levels, reference, CVODE (--rtol, --atol, --method, …), outputs
//   check      converge's, plus --expect-order and --order-tolerance
//   precision  cloud, physics, study levels, reference, outputs, --integrator, the CVODE solver
//              options --linear-solver, --max-steps, --vector, and the sweep --rtol-max,
//              --rtol-min, --per-decade — not --rtol, --atol, --method (it sweeps them)
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "problems/dlp/parameters.hpp"

namespace dlpverify::cli {

enum class Command { converge, check, precision };

struct Options {
  std::string config;  // the study file, read before parsing (see study_file.hpp)
  std::string case_name = "drag";
  std::string integrator = "rk2";  // precision: the fixed-step method beside CVODE
  // cloud (SPEC §2, §8)
  std::string shape = "sphere";
  int outer = 100;
  std::optional<int> inner;        // sphere: 1; shell: outer − 5
  std::optional<double> spacing;   // Δ; default: the particle diameter (particles touch)
  double expansion_speed = 100.0;  // u_s
  Parameters parameters;
  // study (SPEC §6); unset: the case's defaults
  std::optional<double> t_end;
  std::optional<double> dt;
  std::optional<int> levels;
  double ratio = 2.0;
  int threads = 0;  // 0: OpenMP's default
  // reference (SPEC §4): the case's closed form, or CVODE where there is none
  std::optional<std::string> reference;  // exact | cvode; default: exact when the case has a closed form
  // CVODE reference tolerance. precision: kPrecisionReferenceRtol, set by add_options, so the
  // reference stays 100× below the sweep's tightest rtol (1e-12).
  double reference_rtol = 1e-12;
  // CVODE as the integrator under test (--integrator cvode)
  double rtol = 1e-10;
  std::optional<double> atol;      // absolute tolerance per field = atol × the field's scale; default rtol
  std::string method = "adams";    // adams | bdf
  std::string linear_solver = "diag";  // BDF's Newton iteration: diag (CVDiag) | spgmr (matrix-free)
  long max_steps = 100000;
  std::string vector = "serial";   // serial | openmp N_Vector
  // precision: CVODE's rtol sweeps rtol_max, rtol_max/10^(1/per_decade), … down to rtol_min
  double rtol_max = 1e-3;
  double rtol_min = 1e-12;
  int per_decade = 1;
  // outputs
  std::string json_file, csv_file, table_file;
  std::string per_particle_file;  // converge/check: the finest level's error of every particle
  std::string history_file;       // converge/check: the finest level's L2 norms over time
  std::string plot_file;          // the figure: error against Δt, or the work-precision diagram
  std::string title;              // the figure's title; empty: built from the results
  bool plot_relative = false;     // error against Δt as relative L2 norms on one axis
  int history_outputs = 50;
  // check
  std::optional<double> expect_order;
  double order_tolerance = 0.1;
};

// The CVODE reference's default rtol under `precision`.
inline constexpr double kPrecisionReferenceRtol = 1e-14;

// Adds the options of `command` to its subcommand (and, for precision, sets its defaults).
void add_options(CLI::App& app, Options& options, Command command);

// Rejects any value outside its domain with InputError naming the option and the value. Checks
// only the options `command` has.
void validate(const Options& options, Command command);

// Every option of `command` and its value, for the report (after case defaults are filled in).
nlohmann::json to_json(const Options& options, Command command);

// converge (with_check false) and check (true), as study_command.cpp calls them.
inline void add_study_options(CLI::App& app, Options& options, bool with_check) {
  add_options(app, options, with_check ? Command::check : Command::converge);
}
inline void validate(const Options& options, bool with_check) {
  validate(options, with_check ? Command::check : Command::converge);
}
// converge, or check when --expect-order is set.
inline nlohmann::json to_json(const Options& options) {
  return to_json(options, options.expect_order ? Command::check : Command::converge);
}

}  // namespace dlpverify::cli
