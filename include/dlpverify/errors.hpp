/// @file
/// The typed errors of the library. Each names the quantity at fault ("time step", "duration",
/// "relative tolerance", "field x", …) and its value; the command line alone maps a quantity to
/// its option name and an error to an exit code (docs/verification.md, "Exit codes"):
/// @code{.unparsed}
///   0 done · 1 a check failed · 2 bad input · 3 a solver failed · 4 an output could not be written
///   128 + N: a journaled study stopped by signal N between levels (130 SIGINT, 143 SIGTERM)
/// @endcode
#pragma once

#include <stdexcept>
#include <string>

namespace dlpverify {

/// The exit codes of the dlpverify command.
enum ExitCode : int {
  kExitDone = 0,           ///< done
  kExitCheckFailed = 1,    ///< a check failed
  kExitBadInput = 2,       ///< bad input (InputError)
  kExitSolverFailed = 3,   ///< a solver failed (SolverError)
  kExitOutputFailed = 4,   ///< an output could not be written (OutputError)
  kExitInconclusive = 5,   ///< a check could not decide: no failure, but some order not settled within double precision
  kExitStoppedBySignal = 128,  ///< + the signal's number, as a shell reports a process it ended
};

/// Bad input: the quantity, the value it was given and why it is refused.
class InputError : public std::runtime_error {
 public:
  /// what() reads "quantity = value: reason".
  InputError(std::string quantity, std::string value, std::string reason)
      : std::runtime_error(quantity + " = " + value + ": " + reason),
        quantity_(std::move(quantity)),
        value_(std::move(value)),
        reason_(std::move(reason)) {}
  /// A whole-message error: what() and reason() are `message`, quantity() and value() are empty.
  explicit InputError(const std::string& message) : std::runtime_error(message), reason_(message) {}

  const std::string& quantity() const { return quantity_; }  ///< the quantity at fault; empty for a whole-message error
  const std::string& value() const { return value_; }    ///< the value as the user gave it
  const std::string& reason() const { return reason_; }  ///< why it is refused

 private:
  std::string quantity_, value_, reason_;
};

/// A solver gave up (CVODE flags and the like), or a closed form could not be evaluated.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An output file could not be written (a folder that is not writable, a full disk, …).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace dlpverify
