// Running a user's program for one level: argv as given (no shell is involved unless argv names
// one), in a process group of its own so a timeout or a signal reaches it and what it started;
// stdin from /dev/null, stdout discarded (it would mix with our table), stderr kept for the error
// line. The program never outlives the call: once it has ended (success, failure, timeout or
// signal) every process it started, even one that left its group or session, is killed
// (io/process_tree.hpp).
#pragma once

#include <string>
#include <vector>

namespace dlpverify::exchange {

struct CommandResult {
  bool success = false;   // exited with status 0 within the time limit
  std::string ending;     // otherwise: "exited with status 1", "killed by signal 11", "timed out after 5 s"
  std::string last_lines; // the last few non-empty lines of its stderr, joined by " | "
  double seconds = 0.0;   // wall time from start to end
  int signal = 0;         // SIGINT, SIGTERM or SIGHUP that arrived meanwhile and was passed on, or 0
};

// Runs argv[0] (looked up in PATH, environment and working directory kept). After
// `timeout_seconds` the whole process group is killed (SIGKILL); when the program has ended,
// whatever it started and left behind is killed too and reaped. SIGINT, SIGTERM and SIGHUP, where
// they would end this process (their default action), are passed on to the program's group
// meanwhile and reported in `signal` (a second one kills the group): the caller cleans up, then
// raises it again, so the program never outlives us. A signal with a handler (a journaled
// study's stop request) is left to that handler: the level runs to its end; when that handler
// runs once only, the next signal is passed on as one at its default action. Throws ExchangeError
// when the program cannot be started at all (not found, not executable). Calls from several threads
// (a suite's studies side by side) run their programs one after another.
CommandResult run_command(const std::vector<std::string>& argv, double timeout_seconds);

// The last `lines` non-empty lines of `text`, each trimmed, joined by " | ".
std::string last_lines(const std::string& text, int lines);

}  // namespace dlpverify::exchange
