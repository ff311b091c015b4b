// Running another program without a shell: argv as a vector (never a command line), in a folder
// of our choosing, its standard input fed by us through a stdio stream, its standard output
// discarded, its standard error kept in an anonymous file (no pipe to fill up while we write).
// SIGPIPE is blocked while we write, so a program that dies early costs a failed write, not us.
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace dlpverify {

struct ProcessResult {
  bool started = false;       // false: the program could not be run at all (spawn_error says why)
  std::string spawn_error;
  bool exited = false;        // it exited (rather than being killed)
  int exit_status = -1;       // its exit status when it exited
  int signal = 0;             // the signal that ended it otherwise
  bool input_written = false; // feed() returned true and every byte reached the pipe
  std::string standard_error; // up to 1 MiB of what it wrote to stderr
};

// Runs argv[0] (looked up in PATH) in `folder` with argv, handing `feed` the write end of its
// standard input as a FILE*, which feed owns and must close (fclose, or an object that does, such
// as gnuplot-iostream's stream) before it returns: the program sees the end of its input then.
// Waits for the program. Throws SolverError only when the system refuses a pipe or a file.
ProcessResult run_program(const std::vector<std::string>& argv, const std::string& folder,
                          const std::function<bool(std::FILE* input)>& feed);

}  // namespace dlpverify
