// converge and check of a named case: options → case → integrator → study (dlpverify/study_request.hpp)
// → result files, under a journal that a signal stops between levels.
#pragma once

#include <string>

#include "case_study/options.hpp"
#include "case_study/outcome.hpp"

namespace dlpverify::case_study {

// The study `options` describe, and the verdict when `check` (the same options, plus the expected
// order; may be null) is given; with --tolerances, the tolerance study (case_study/tolerance.hpp).
// Writes the requested files together (io/atomic_file.hpp) and leaves the console table to the
// caller. Throws InputError for bad input — before any output exists — and SolverError when a
// solver fails. `options` gets the case's defaults filled in.
CaseOutcome run_case(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line);

}  // namespace dlpverify::case_study
