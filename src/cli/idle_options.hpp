// Options that do nothing in the mode the other options choose are refused, not ignored: a user
// who gives --budget with --levels 4, or --block-tol without --adaptive, believes it acts
// (docs/cli.md, "Options that do nothing"). An option counts as given when it is typed or is a
// key of the study file; the mode is the options' final values (a typed option overrides the file's).
#pragma once

namespace dlpverify::cli {

struct CommandLine;

// Throws InputError naming the first option given that does nothing, its value and why; after
// CommandLine::parse.
void refuse_idle_options(const CommandLine& line);

}  // namespace dlpverify::cli
