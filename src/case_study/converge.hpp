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

// The reports a CI shows, for a check that ended without a verdict after `seconds` (a solver or the
// program under test failed, exit 3): --junit as one error case holding `line` and `code`,
// --summary as one ERROR row, written together and atomically as a finished check's outputs are,
// on rank 0 alone. Nothing is written where the path rules refuse a path (the failure may have
// come before they ran). OutputError when an output cannot be written.
void write_failure_reports(const CheckOptions& check, int code, const std::string& line, double seconds);

}  // namespace dlpverify::case_study
