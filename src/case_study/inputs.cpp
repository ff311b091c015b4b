#include "case_study/inputs.hpp"

#include <optional>

#include "families/families.hpp"
#include "families/study_integrators.hpp"
#include "study/journal.hpp"

namespace dlpverify::case_study {

using namespace families;

namespace {

void add(std::vector<NamedPath>& inputs, const std::string& name, const std::string& path) {
  if (!path.empty()) inputs.push_back({name, path});
}

}  // namespace

std::vector<NamedPath> integrator_inputs(const std::string& option, const std::string& spec) {
  std::vector<NamedPath> inputs;
  const std::optional<IntegratorCatalog::Found> found = study_catalog().find(spec);
  if (found && found->entry->argument_files)
    for (const ArgumentFile& file : found->entry->argument_files(found->argument)) add(inputs, option + " " + file.what, file.path);
  return inputs;
}

std::vector<NamedPath> study_inputs(const ConvergeOptions& options, const CheckOptions* check) {
  std::vector<NamedPath> inputs;
  add(inputs, "--config", options.config);
  for (NamedPath& p : integrator_inputs("--integrator", options.integrator)) inputs.push_back(std::move(p));
  if (options.reference.kind)
    if (const std::optional<IntegratorReferenceOption> reference = integrator_reference_option(*options.reference.kind))
      for (NamedPath& p : integrator_inputs("--reference", reference->integrator)) inputs.push_back(std::move(p));
  if (check) add(inputs, "--baseline", check->baseline);
  return inputs;
}

std::vector<NamedPath> study_inputs(const PrecisionOptions& options) {
  std::vector<NamedPath> inputs;
  add(inputs, "--config", options.config);
  return inputs;
}

std::vector<NamedPath> named_paths(const std::vector<std::pair<std::string, std::string>>& outputs, bool journaled) {
  std::vector<NamedPath> named;
  if (journaled)
    for (const auto& [option, path] : outputs)
      if (option == "--json" && !path.empty() && !journal_path(path).empty())
        named.push_back({"the journal beside " + option, journal_path(path)});
  for (const auto& [option, path] : outputs)
    if (!path.empty()) named.push_back({option, path});
  return named;
}

}  // namespace dlpverify::case_study
