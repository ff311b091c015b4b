// The verdict on a sharpness measurement (sharpness.hpp) and its report: the tableau as written
// must pass its own check (fitted order within the tolerance of its claimed order) for its
// mutants to be judged at all, and the measurement passes when every mutant is caught by some
// check (docs/verification.md, "How sharp is the check").
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "integrators/tableau/sharpness.hpp"

namespace dlpverify {

struct SharpnessOutcome {
  CheckVerdict unperturbed;  // the tableau as written against its claimed order
  bool passed = false;       // it passes, and every mutant is caught
  std::string table;         // the console report: each mutant and what caught it, or why none was judged
  nlohmann::json report;     // the JSON result, less the options and provenance
};

// `case_name` and `reference` name the study, `alternative` the alternative reference ("none").
SharpnessOutcome judge_sharpness(const RuntimeTableau& tableau, const SharpnessReport& report,
                                 const std::string& case_name, const std::string& reference,
                                 const std::string& alternative);

}  // namespace dlpverify
