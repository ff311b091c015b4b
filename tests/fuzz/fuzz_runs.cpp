// libFuzzer target: the runs `dlpverify analyze` reads (docs/analyze.md) as CSV files — a header of
// field names (and `id`), an optional "# units:" line, one row per member. The input is split at
// NUL bytes into up to four runs, written to files and read as one study would read them: steps
// 10, 20, 40, 80 over 0.02 s (the --dt and --t-end of a CSV study), members matched by id or by
// position, fields checked against the first run, the refinement checked. The text after the last
// NUL, when it holds an '=', is also parsed as a --variable. Bad input must end as an InputError
// (exit 2); any other exception, a crash, a hang or a sanitizer report is a finding.
//
// HDF5 runs are left out: bytes with the HDF5 signature are skipped, because a malformed HDF5 file
// exercises the HDF5 library's own parser, not ours (its checks of the fields are the same code
// as the exec: exchange's, covered by cli.exec-* tests).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "dlpverify/errors.hpp"
#include "exchange/run_set.hpp"

namespace {

// A scratch folder for the runs' files, made once per fuzzing process and removed at its exit (by
// the static's destructor: an atexit handler registered inside its initialisation would run after
// that destructor and read a destroyed string).
struct ScratchFolder {
  std::string path = "/tmp/dlpverify-fuzz-runs-XXXXXX";
  ScratchFolder() {
    if (mkdtemp(path.data()) == nullptr) std::abort();
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

const std::string& scratch_folder() {
  static const ScratchFolder folder;
  return folder.path;
}

std::vector<std::string> split_at_nul(const std::string& bytes) {
  std::vector<std::string> parts(1);
  for (char c : bytes) {
    if (c == '\0') parts.emplace_back();
    else parts.back() += c;
  }
  return parts;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> parts = split_at_nul(bytes);
  std::string variable;
  if (parts.size() > 1 && parts.back().find('=') != std::string::npos && parts.back().find('\n') == std::string::npos) {
    variable = parts.back();
    parts.pop_back();
  }
  if (parts.size() > 4) parts.resize(4);
  dlpverify::exchange::RunRequest request;
  double dt = 2e-3;
  for (std::size_t k = 0; k < parts.size(); ++k, dt /= 2.0) {
    if (parts[k].rfind("\x89HDF", 0) == 0) return 0;  // not ours to parse (see above)
    const std::string path = scratch_folder() + "/run" + std::to_string(k) + ".csv";
    std::ofstream(path, std::ios::binary | std::ios::trunc) << parts[k];
    request.paths.push_back(path);
    request.dt.push_back(dt);
  }
  request.duration = 0.02;
  try {
    if (!variable.empty()) request.variables.push_back(dlpverify::exchange::parse_variable(variable));
    (void)dlpverify::exchange::read_runs(request);
  } catch (const dlpverify::InputError&) {
  }
  return 0;
}
