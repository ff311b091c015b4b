// What a case study leaves its caller to print, after every output file is written.
#pragma once

#include <string>

#include "dlpverify/errors.hpp"

namespace dlpverify::case_study {

struct CaseOutcome {
  int exit_code = kExitDone;  // docs/verification.md, "Exit codes"; 128 + N when signal N stopped the study
  // The console table; empty when an output goes to standard output instead, on a rank other than
  // 0 (the command's outcome is rank 0's) and when a signal stopped the study.
  std::string console;
};

}  // namespace dlpverify::case_study
