// libFuzzer target: the words a user types after `dlpverify`. The input is split at NUL bytes into
// words, which are parsed by the command's own parser (cli/command_line.hpp) and, when they parse,
// checked as the command checks them before any work (parsed_options.hpp). No study file is read
// here (fuzz_study_file.cpp reads them from bytes). Bad input must end as an InputError (exit 2)
// or as --help/--version; any other exception, a crash, a hang or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "dlpverify/errors.hpp"
#include "parsed_options.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> words(1);
  for (std::size_t i = 0; i < size; ++i)
    if (data[i] == '\0')
      words.emplace_back();
    else
      words.back() += static_cast<char>(data[i]);
  dlpverify::cli::CommandLine line;
  try {
    line.parse(words);
    dlpverify::fuzz::check_parsed(line);
  } catch (const dlpverify::InputError&) {
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) throw;  // parse() must have made it an InputError
  }
  return 0;
}
