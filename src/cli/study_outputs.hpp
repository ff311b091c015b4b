// The result files of a finished study as converge, check and analyze write them: the figure
// (error against Δt), JSON, CSV and the console table, staged in the caller's OutputSet so that
// they are committed together with the caller's other outputs (io/atomic_file.hpp).
#pragma once

#include <optional>
#include <string>

#include "cli/options.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/report.hpp"
#include "io/atomic_file.hpp"

namespace dlpverify::cli {

// Adds the outputs `files` asks for to `outputs` and returns the console table (printed by the
// caller after the commit, unless an output goes to standard output).
std::string add_study_outputs(OutputSet& outputs, const OutputOptions& files, bool plot_relative,
                              const StudyDescription& description, const StudyResult& study,
                              const std::optional<CheckVerdict>& verdict);

}  // namespace dlpverify::cli
