// Every failure as the command reports it: an exit code and one line (docs/verification.md, "Exit
// codes"). The library names quantities; this maps each to the option that sets it.
#pragma once

#include <exception>
#include <string>

#include "dlpverify/errors.hpp"

namespace dlpverify::cli {

// A verdict's exit codes as the --help of check and analyze, and so the man page, give them:
// "exit 0 pass, 1 fail, 5 inconclusive", from the codes themselves.
std::string verdict_exit_codes();

// "--dt = 0: must be positive": the quantity as its option, the value printable and cut.
std::string input_error_line(const InputError& e);

// A failure as the exit code and the one line the command prints for it.
struct Failure {
  int code;
  std::string line;
};

// The failure `failure` holds: InputError 2, OutputError 4, SolverError and every other error 3.
Failure failure_of(std::exception_ptr failure);

// Prints "dlpverify: " + line to stderr, printable (no control byte reaches the terminal) and cut
// to a few screen lines.
void report(const std::string& line);

}  // namespace dlpverify::cli
