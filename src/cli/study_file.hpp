// Study files: `--config verification/drag-rk2.toml` holds `key = value` lines whose keys are the
// long option names (t-end = 0.01, integrator = "rk2", …), in TOML (docs/cli.md, "Study files").
//
// CLI11 2.1 (Debian's) does not read a config file given to a subcommand, and its reader is not
// TOML (it takes `case = drag` unquoted and an unterminated "drag literally), so the file is
// parsed here by toml++ and each key is checked against its option's type before it becomes one
// `--key=value` word. The words go ahead of the typed options, which take precedence (options
// take their last value): what is typed overrides the file.
#pragma once

#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace dlpverify::cli {

// args: the words after the subcommand's name. Returns them with the study file's keys inserted
// first. Throws InputError naming --config for a missing, empty or unreadable file name, a file
// that is not TOML, an unknown key or a value of the wrong type.
std::vector<std::string> expand_study_file(const CLI::App& subcommand, const std::vector<std::string>& args);

// The study file's keys as options ("--t-end=0.01", …), in the order the file gives them, read
// from `text`; `path` names the file in errors.
std::vector<std::string> study_file_options(const CLI::App& subcommand, const std::string& path, std::string_view text);
std::vector<std::string> study_file_options(const CLI::App& subcommand, const std::string& path, std::istream& text);

}  // namespace dlpverify::cli
