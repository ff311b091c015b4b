// GSL reports errors through a process-wide handler whose default calls abort(). dlpverify checks
// GSL's return codes (and NaN results) instead: every GSL caller calls use_gsl_return_codes()
// first, so the handler is off before any GSL function runs, whichever runs first.
//
// gsl_set_error_handler is process-global and not thread-safe to toggle around a call, so it is
// switched off exactly once (a function-local static: C++ guarantees one thread-safe
// initialisation) and never switched back.
#pragma once

namespace dlpverify {

void use_gsl_return_codes();

}  // namespace dlpverify
