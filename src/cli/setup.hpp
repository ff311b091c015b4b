// What converge, check and precision share: options → case (its defaults filled in) → problem,
// levels and reference, all validated before any work is done or any file exists.
#pragma once

#include <memory>

#include "cli/options.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify::cli {

struct StudySetup {
  std::unique_ptr<Problem> problem;
  StudyPlan plan;  // levels and measured variables; expected_order is the caller's
  ReferenceSettings reference;
};

// Fills the case's defaults into already validated options (so reports show what was run),
// refuses a duration the problem cannot take, a step count that is not whole, an output that
// cannot be written, and a closed form whose audit fails on these parameters (docs/model.md §4).
// Throws InputError naming the option and its value (OutputError for an unwritable output).
StudySetup resolve_setup(ProblemOptions& problem, LevelOptions& levels, ReferenceOptions& reference,
                         const SolverOptions& solver, const std::vector<std::pair<std::string, std::string>>& outputs);

}  // namespace dlpverify::cli
