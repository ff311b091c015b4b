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

// A finished study as it is reported: the console table and the JSON result, each with whatever
// the command adds to them (the level search, the reasons for a missed order).
struct StudyReport {
  std::string table;
  nlohmann::json result;
};

// The report of format_table and to_json, before the command adds to it.
StudyReport study_report(const StudyDescription& description, const StudyResult& study,
                         const std::optional<CheckVerdict>& verdict);

// Adds the outputs `files` asks for to `outputs`: the figure and the JSON from report.result, the
// CSV from the study, the table file from report.table (printed by the caller after the commit,
// unless an output goes to standard output).
void add_study_outputs(OutputSet& outputs, const OutputOptions& files, bool plot_relative,
                       const StudyDescription& description, const StudyResult& study, const StudyReport& report);

}  // namespace dlpverify::cli
