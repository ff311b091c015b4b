// sharpness of a named case: how sharp a verification is, by perturbing each coefficient of a
// tableau:FILE alone and studying every mutant on the case (integrators/tableau/sharpness.hpp).
#pragma once

#include <string>

#include "case_study/options.hpp"
#include "case_study/outcome.hpp"

namespace dlpverify::case_study {

// The perturbations and what caught each: --json written (io/atomic_file.hpp) and the table left
// to the caller. Exit code 0 when some check catches every perturbation, 1 when one escapes them
// all (or the tableau as written fails its own check on the case); InputError for bad input,
// before any work or output.
CaseOutcome run_sharpness(SharpnessOptions& options, const std::string& command_line);

}  // namespace dlpverify::case_study
