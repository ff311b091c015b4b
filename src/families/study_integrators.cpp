#include "families/study_integrators.hpp"

#include "dlpverify/errors.hpp"
#include "families/family.hpp"

namespace dlpverify::families {

namespace {

// Each family's own schemes (the gas model's temperature updates), for its cases alone.
std::vector<IntegratorEntry> problem_schemes() {
  std::vector<IntegratorEntry> entries;
  for (const Family* family : families())
    for (IntegratorInfo& info : family->integrators()) {
      const std::string name = info.name;
      entries.push_back({std::move(info),
                         [family, name](const std::string&, const IntegratorContext&) { return family->make_integrator(name); },
                         {}, family->title(), {}, {}});
    }
  return entries;
}

}  // namespace

const IntegratorCatalog& study_catalog() {
  static const IntegratorCatalog catalog = study_integrators(problem_schemes());
  return catalog;
}

std::vector<IntegratorInfo> known_study_integrators() {
  std::vector<IntegratorInfo> list;
  for (const IntegratorEntry& entry : study_catalog().levels()) list.push_back(entry.info);
  return list;
}

std::optional<IntegratorTraits> find_integrator_traits(const std::string& spec) {
  if (const std::optional<IntegratorCatalog::Found> found = study_catalog().find(spec))
    return found->entry->argument_traits ? found->entry->argument_traits(found->argument) : found->entry->info.traits;
  return std::nullopt;
}

IntegratorTraits integrator_traits(const std::string& spec) {
  if (std::optional<IntegratorTraits> traits = find_integrator_traits(spec)) return *traits;
  throw InputError("integrator", spec, "unknown integrator (see `dlpverify cases`)");
}

std::unique_ptr<Integrator> make_study_integrator(const std::string& name, const CvodeSettings& cvode,
                                                  const std::string& case_name, const exchange::ExecSettings& exec) {
  const std::optional<IntegratorCatalog::Found> found = study_catalog().find(name);
  if (found && !found->entry->family.empty() && found->entry->family != family_of(case_name).title())
    for (const Family* family : families())
      if (family->title() == found->entry->family) {
        std::string cases;
        for (const CaseEntry& c : family->cases()) cases += (cases.empty() ? "" : ", ") + c.name;
        throw InputError("integrator", name, "integrates " + family->title() + " only; use it with --case " + cases);
      }
  if (found && found->entry->make)
    if (std::unique_ptr<Integrator> integrator = found->entry->make(found->argument, IntegratorContext{cvode, exec, std::nullopt}))
      return integrator;
  // An unknown name, or arkode-erk: with a table ARKODE does not have: refused there, naming it.
  return make_integrator(name, cvode);
}

}  // namespace dlpverify::families
