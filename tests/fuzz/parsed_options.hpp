// What the fuzz targets of the command line do with words that parsed: what the command does with
// them before any work — validate every option (InputError naming it), look up the case and the
// integrator, report the options as the JSON would — and nothing after (no cloud, no study, no file).
#pragma once

#include "cli/command_line.hpp"
#include "cli/options.hpp"
#include "cli/problems.hpp"
#include "io/format.hpp"
#include "integrators/registry.hpp"

namespace dlpverify::fuzz {

template <class Options>
void check_study_options(const Options& options) {
  cli::validate(options);
  cli::find_case_entry(options.problem.case_name);
  (void)make_integrator(options.integrator, cli::cvode_settings({}, options.solver));
  (void)json_text(cli::to_json(options), 2);  // as the JSON and CSV outputs write them
  (void)cli::output_files(options);
}

inline void check_parsed(const cli::CommandLine& line) {
  if (line.converge->parsed()) check_study_options(line.converge_options);
  if (line.check->parsed()) check_study_options(line.check_options);
  if (line.precision->parsed()) check_study_options(line.precision_options);
}

}  // namespace dlpverify::fuzz
