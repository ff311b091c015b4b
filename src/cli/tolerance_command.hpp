// converge and check with --tolerances MAX:MIN: an adaptive integrator (cvode,
// arkode-adaptive:TABLE with an explicit or implicit table, or exec:COMMAND taking {rtol}) run
// once per tolerance, its error's exponent against rtol fitted and, for check, judged
// (dlpverify/tolerance_study.hpp).
#pragma once

#include <string>

#include "cli/options.hpp"

namespace dlpverify::cli {

// The tolerance study of `options`; `check` (the same options) adds the verdict. Returns the exit code.
int run_tolerance_study(ConvergeOptions& options, const CheckOptions* check, const std::string& command_line);

}  // namespace dlpverify::cli
