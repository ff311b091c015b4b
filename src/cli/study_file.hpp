// Study files: `--config verification/drag-rk2.toml` holds `key = value` lines whose keys are the
// long option names (t-end = 0.01, integrator = "rk2", …).
//
// CLI11 2.1 (Debian's) does not read a config file given to a subcommand, so the file is read
// here with CLI11's own TOML reader and its keys are put ahead of the typed options, which take
// precedence (options take their last value): what is typed overrides the file.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace dlpverify::cli {

// args: the words after the subcommand's name. Returns them with the study file's keys inserted
// first. Throws InputError naming --config for a missing file, an unknown key or a bad entry.
std::vector<std::string> expand_study_file(const CLI::App& subcommand, const std::vector<std::string>& args);

// The study file's keys as options ("--t-end=0.01", …), read from `text`; `path` names it in errors.
std::vector<std::string> study_file_options(const CLI::App& subcommand, const std::string& path, std::istream& text);

}  // namespace dlpverify::cli
