#include "cli/study_inputs.hpp"

#include <sstream>

#include <sys/stat.h>

namespace dlpverify::cli {

namespace {

bool names_a_file(const std::string& word) {
  struct stat st {};
  return word.find('{') == std::string::npos && ::stat(word.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// A word of a command with the shell's quotes around it taken off.
std::string unquoted(std::string word) {
  if (word.size() >= 2 && (word.front() == '\'' || word.front() == '"') && word.back() == word.front())
    word = word.substr(1, word.size() - 2);
  return word;
}

void add(std::vector<NamedPath>& inputs, const std::string& name, const std::string& path) {
  if (!path.empty()) inputs.push_back({name, path});
}

}  // namespace

std::vector<NamedPath> integrator_inputs(const std::string& option, const std::string& spec) {
  std::vector<NamedPath> inputs;
  if (spec.rfind("tableau:", 0) == 0) add(inputs, option + " tableau file", spec.substr(8));
  if (spec.rfind("exec:", 0) == 0) {
    std::istringstream words(spec.substr(5));
    for (std::string word; words >> word;)
      if (names_a_file(unquoted(word))) add(inputs, option + " program", unquoted(word));
  }
  return inputs;
}

std::vector<NamedPath> study_inputs(const ConvergeOptions& options, const CheckOptions* check) {
  std::vector<NamedPath> inputs;
  add(inputs, "--config", options.config);
  for (NamedPath& p : integrator_inputs("--integrator", options.integrator)) inputs.push_back(std::move(p));
  // --reference integrator:SPEC@DT: SPEC ends at the last '@'.
  const std::string reference = options.reference.kind.value_or("");
  if (reference.rfind("integrator:", 0) == 0 && reference.rfind('@') != std::string::npos)
    for (NamedPath& p : integrator_inputs("--reference", reference.substr(11, reference.rfind('@') - 11)))
      inputs.push_back(std::move(p));
  if (check) add(inputs, "--baseline", check->baseline);
  return inputs;
}

std::vector<NamedPath> study_inputs(const PrecisionOptions& options) {
  std::vector<NamedPath> inputs;
  add(inputs, "--config", options.config);
  return inputs;
}

std::vector<NamedPath> named_paths(const std::vector<std::pair<std::string, std::string>>& outputs) {
  std::vector<NamedPath> named;
  for (const auto& [option, path] : outputs)
    if (!path.empty()) named.push_back({option, path});
  return named;
}

}  // namespace dlpverify::cli
