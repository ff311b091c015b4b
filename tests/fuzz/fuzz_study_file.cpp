// libFuzzer target: a study file (`--config FILE`, TOML key = value lines). The input is the file's
// bytes, read as a study subcommand reads it (cli/study_file.hpp); the options it yields are
// parsed and checked as the command checks them before any work (parsed_options.hpp). Bad input
// must end as an InputError (exit 2); anything else that escapes, a crash, a hang or a sanitizer
// report is a finding.
#include <array>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "cli/study_file.hpp"
#include "dlpverify/errors.hpp"
#include "parsed_options.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // One subcommand per input (building the parser is most of the cost), chosen by its length.
  const char* subcommand = std::array{"converge", "check", "precision"}[size % 3];
  dlpverify::cli::CommandLine line;
  try {
    std::istringstream in(text);
    std::vector<std::string> words =
        dlpverify::cli::study_file_options(*line.study_subcommand(subcommand), "study.toml", in);
    words.insert(words.begin(), subcommand);
    line.parse(words);
    dlpverify::fuzz::check_parsed(line);
  } catch (const dlpverify::InputError&) {
  }
  return 0;
}
