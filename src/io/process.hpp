// Running a helper program (gnuplot) without a shell: argv goes to posix_spawnp as it is, so no
// text of ours or the user's is ever parsed by /bin/sh.
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace dlpverify {

struct ProcessResult {
  bool success = false;  // exited with status 0 after taking all its input
  std::string output;    // all it wrote on stdout
  std::string errors;    // its stderr (the first MiB)
  std::string ending;    // how it ended when not successfully: "exited with status 1", "killed by signal 9" …
  int signal = 0;        // the signal that ended it; 0 when it exited
};

// Runs argv[0] (found in PATH, environment kept) with stdin a pipe and stdout and stderr in memory
// files, so neither can fill up and stall it while we write (memory files count against the
// file-size limit, ulimit -f: a child writing past it is ended by SIGXFSZ). `feed` gets the pipe as a stdio
// stream, owns it (it must fclose it; gnuplot-iostream's Gnuplot does when destroyed) and returns
// whether it wrote everything; an exception from it counts as false. SIGPIPE is blocked in this
// thread meanwhile: a child that dies early costs a failed write, not this process.
// Throws SolverError when the program cannot be started.
ProcessResult run_process(const std::vector<std::string>& argv, const std::function<bool(std::FILE*)>& feed);

// Starts argv[0] (found in PATH, environment kept, no shell) with stdin, stdout and stderr on the
// given descriptors, and sets pid. The child starts with no signal blocked and every signal at its
// default action; with `own_group` it leads a new process group (its id is its pid). Returns 0, or
// posix_spawnp's error number when the program cannot be started.
int spawn_program(const std::vector<std::string>& argv, int in, int out, int err, bool own_group, pid_t& pid);

}  // namespace dlpverify
