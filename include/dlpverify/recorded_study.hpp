/// @file
/// A finished study as its JSON result records it (docs/verification.md, "The JSON result"), read
/// back for what compares two studies: the baseline gate of a check (StudyExpectation::baseline)
/// and `dlpverify compare`. What must match for two studies to be compared — the same case,
/// parameters, reference and levels — is their identity; the integrator is what may differ.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/study.hpp"

namespace dlpverify {

/// C of e ≈ C Δt^p as recorded (`error_constant.<var>`).
struct RecordedConstant {
  double value = 0.0;                  ///< C
  double order = 0.0;                  ///< p, held fixed in the fit
  double ci_low = 0.0;                 ///< C's 95% interval, low end; NaN when the fit had one level
  double ci_high = 0.0;                ///< its high end; NaN when the fit had one level
  std::vector<int> levels;             ///< the levels fitted
};

/// One measured variable over the levels.
struct RecordedVariable {
  std::string name;                             ///< the variable's name
  std::vector<double> error;                    ///< `l2_<var>` per level; NaN where null
  std::vector<std::optional<double>> pairwise;  ///< `order_<var>` per level
  std::optional<double> order;                  ///< `fitted_order.<var>.value`
  bool exact_to_round_off = false;              ///< every level at the round-off floor
  std::optional<RecordedConstant> constant;     ///< none when the study fitted none
};

/// A converge or check result as recorded.
struct RecordedStudy {
  std::string source;        ///< the file it was read from, for messages
  std::string integrator;    ///< what may differ between compared studies
  nlohmann::json identity;   ///< what may not: case, parameters, particles, t0, t_end, ratio, reference, variables
  std::vector<double> dt;    ///< per level
  std::vector<long> steps;   ///< per level
  std::vector<RecordedVariable> variables;  ///< in the result's order
};

/// Reads a converge or check result. InputError(quantity, source, reason) when `result` is not one
/// (a missing key, or written before results recorded their error constants).
RecordedStudy read_recorded_study(const nlohmann::json& result, const std::string& source, const std::string& quantity);
/// The same from a file: InputError naming `quantity` and the path when it cannot be read or parsed.
RecordedStudy read_recorded_study_file(const std::string& path, const std::string& quantity);

/// The variables of a study in memory, as its JSON result would record them.
std::vector<RecordedVariable> recorded_variables(const StudyResult& study);

struct StudyDescription;
/// A study in memory as its JSON result would record it (`source` names it in messages).
RecordedStudy recorded_study(const StudyDescription& description, const StudyResult& study, const std::string& source);

/// The first thing in which b's identity or levels differ from a's, as "its case is \"full\",
/// not \"drag\""; empty when the two are studies of the same case, parameters and levels.
std::string study_difference(const RecordedStudy& a, const RecordedStudy& b);

}  // namespace dlpverify
