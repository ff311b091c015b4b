// Every option of `dlpverify converge` and `check`, with its documented default. CLI11 binds
// this one struct, and a study file (--config) holds the same keys, so a flag and a file never
// disagree. Options left unset take the case's defaults (t-end, dt, levels).
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "model/parameters.hpp"

namespace dlpverify::cli {

struct Options {
  std::string config;  // the study file, read before parsing (see study_file.hpp)
  std::string case_name = "drag";
  std::string integrator = "rk2";
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
  double reference_rtol = 1e-12;
  // CVODE as the integrator under test (--integrator cvode)
  double rtol = 1e-10;
  std::optional<double> atol;      // absolute tolerance per field = atol × the field's scale; default rtol
  std::string method = "adams";    // adams | bdf
  std::string linear_solver = "diag";  // BDF's Newton iteration: diag (CVDiag) | spgmr (matrix-free)
  long max_steps = 100000;
  std::string vector = "serial";   // serial | openmp N_Vector
  // outputs
  std::string json_file, csv_file, table_file;
  // check
  std::optional<double> expect_order;
  double order_tolerance = 0.1;
};

// Adds the study options (and, for `check`, the order options) to a subcommand.
void add_study_options(CLI::App& app, Options& options, bool with_check);

// Rejects any value outside its domain with InputError naming the option and the value.
void validate(const Options& options, bool with_check);

// Every option and its value, for the report (after case defaults are filled in).
nlohmann::json to_json(const Options& options);

}  // namespace dlpverify::cli
