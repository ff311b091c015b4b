// The files a run reads, named as the user named them, so that no output may be one of them
// (io/file_identity.hpp: by identity, however spelled).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "case_study/options.hpp"
#include "io/file_identity.hpp"

namespace dlpverify::case_study {

/// The files an integrator SPEC names: a tableau:FILE's file, and each word of an exec:COMMAND
/// that names an existing file (the program, a script it runs); named `option` in messages.
std::vector<NamedPath> integrator_inputs(const std::string& option, const std::string& spec);

/// A study's inputs: its study file, its integrator's and an integrator reference's files, and
/// `check`'s baseline (check may be null), of options that validate() took.
std::vector<NamedPath> study_inputs(const ConvergeOptions& options, const CheckOptions* check);
std::vector<NamedPath> study_inputs(const PrecisionOptions& options);

/// Output options and paths as named paths. `journaled`: the run keeps a journal beside its --json
/// (study/journal.hpp), which it writes and removes like an output, so it comes first among them:
/// an output on it is refused naming that output.
std::vector<NamedPath> named_paths(const std::vector<std::pair<std::string, std::string>>& outputs,
                                   bool journaled = false);

}  // namespace dlpverify::case_study
