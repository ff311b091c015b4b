// precision of a named case: a work-precision study. CVODE Adams and BDF over a sweep of relative
// tolerances (atol = rtol × each field's size), and a fixed-step method (rk2 by default) at the
// study levels, each measured against the case's reference: error against RHS evaluations and
// wall time.
#pragma once

#include <string>

#include "case_study/options.hpp"
#include "case_study/outcome.hpp"

namespace dlpverify::case_study {

// The study `options` describe (their case's defaults filled in), its requested files written
// together (io/atomic_file.hpp) and the console table left to the caller; exit code 0. Throws
// InputError for bad input — before any work or output — and SolverError, naming the case and the
// run, when a solver fails (no file is written then).
CaseOutcome run_precision(PrecisionOptions& options, const std::string& command_line);

}  // namespace dlpverify::case_study
