// The result files of a finished study as converge, check and analyze write them: the figure
// (error against Δt), JSON, CSV and the console table, staged in the caller's OutputSet so that
// they are committed together with the caller's other outputs (io/atomic_file.hpp).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "case_study/options.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study.hpp"
#include "io/atomic_file.hpp"

namespace dlpverify::case_study {

// Adds the outputs `files` asks for to `outputs`: the figure and the JSON from `result`, the CSV
// from the study, the table file from `table` (printed by the caller after the commit, unless an
// output goes to standard output).
void add_study_outputs(OutputSet& outputs, const OutputOptions& files, bool plot_relative,
                       const StudyDescription& description, const StudyResult& study, const nlohmann::json& result,
                       const std::string& table);

}  // namespace dlpverify::case_study
