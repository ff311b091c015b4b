// The one error boundary: typed exceptions that main() turns into one line and an exit code.
//   0 done · 1 a check failed · 2 bad input · 3 a solver failed
#pragma once

#include <stdexcept>
#include <string>

namespace dlpverify {

enum ExitCode : int { kExitDone = 0, kExitCheckFailed = 1, kExitBadInput = 2, kExitSolverFailed = 3 };

// Bad input: names the option and the value it was given.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& option, const std::string& value, const std::string& reason)
      : std::runtime_error(option + " = " + value + ": " + reason) {}
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// A solver gave up (CVODE flags and the like), or an output could not be written.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace dlpverify
