// The runs `dlpverify analyze` is given (docs/analyze.md): files a user's program wrote, one per
// time step — the exchange format's HDF5 (its /fields with the step and time as root attributes)
// or a CSV of one header line of field names and one row per member — read, checked against each
// other and put in the shape of a study's levels: the measured columns of every run, members in
// one order, coarsest run first.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify::exchange {

// A measured variable as the user names it: its fields, and its unit when one is given.
struct VariableSpec {
  std::string name;
  std::vector<std::string> fields;
  std::string unit;  // empty: the fields' own (which must agree)
};

// What to read: the run files, the optional reference, and for CSV runs their steps (--dt in the
// order of `paths`) and the duration they cover (--t-end); HDF5 runs carry both.
struct RunRequest {
  std::vector<std::string> paths;
  std::string reference;     // empty: none
  std::string reference_check;  // the reference's program at half its step, for its error; empty: none
  std::vector<double> dt;    // CSV runs: one step per path
  std::optional<double> duration;  // CSV runs: t_end − t0
  std::vector<VariableSpec> variables;  // empty: each field its own variable
};

// The runs read: every state holds the measured columns of `variables`, members in the order of
// the first run read (by the `id` column when the runs have one, by position otherwise).
struct RunSet {
  std::vector<std::string> paths;  // coarsest first
  std::vector<long> steps;         // of each run, coarsest first
  std::vector<State> states;       // measured columns, coarsest first
  std::optional<State> reference;  // the reference's measured columns
  std::optional<State> reference_check;  // the same at half the reference's step
  std::vector<Variable> variables;
  double t0 = 0.0;        // the runs' start time (0 for CSV runs)
  double duration = 0.0;  // t_end − t0, the same for every run
  bool matched_by_id = false;
};

// Reads and checks the runs. Throws InputError with one line naming the run (or option) and what
// differs: a field, the member count, the end time, a member id, the steps' refinement.
RunSet read_runs(const RunRequest& request);

// "name=f1,f2,…" (--variable) as a VariableSpec; throws InputError naming --variable.
VariableSpec parse_variable(const std::string& text);
// The [[variable]] tables of a TOML file (name, fields, optional unit); throws InputError naming
// --variables and the file.
std::vector<VariableSpec> read_variables_file(const std::string& path);

}  // namespace dlpverify::exchange
