// converge and check with --tolerances MAX:MIN: an adaptive integrator (cvode,
// arkode-adaptive:TABLE with an explicit or implicit table, or exec:COMMAND taking {rtol}) run
// once per tolerance, its error's exponent against rtol fitted and, for check, judged
// (dlpverify/tolerance_study.hpp).
#pragma once

#include <string>

#include "case_study/options.hpp"
#include "case_study/outcome.hpp"

namespace dlpverify::case_study {

// The tolerance study of `options`; `check` (the same options) adds the verdict.
CaseOutcome run_tolerance_study(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line);

}  // namespace dlpverify::case_study
