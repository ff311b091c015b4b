#include "cli/problems.hpp"

#include <algorithm>
#include <iostream>

#include "cli/family.hpp"
#include "cli/option_checks.hpp"
#include "dlpverify/errors.hpp"

namespace dlpverify::cli {

const std::vector<const Family*>& families() {
  static const std::vector<const Family*> list{&dlp_family(), &gas_family(), &thermal_family()};
  return list;
}

bool Family::closed_form(const ProblemOptions& o) const { return find_case_entry(o.case_name).closed_form; }

BaselineAudit named_audit(const std::string& name, bool published, const std::string& source, const Problem& sample,
                          double t_end) {
  BaselineAudit audit = audit_closed_form(sample, t_end);
  audit.baseline = name;
  audit.published = published;
  audit.source = source;
  return audit;
}

std::vector<CaseEntry> all_cases() {
  std::vector<CaseEntry> entries;
  for (const Family* family : families())
    for (CaseEntry& entry : family->cases()) entries.push_back(std::move(entry));
  return entries;
}

const CaseEntry& find_case_entry(const std::string& name) {
  static const std::vector<CaseEntry> entries = all_cases();
  std::string names;
  for (const CaseEntry& c : entries) {
    if (c.name == name) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throw InputError("--case", name, "unknown case (known: " + names + ")");
}

const Family& family_of(const std::string& case_name) {
  const std::string& problem = find_case_entry(case_name).problem;
  for (const Family* family : families())
    if (family->name() == problem) return *family;
  throw InputError("--case", case_name, "belongs to no problem family");  // unreachable: entries come from families
}

std::string problem_of_case(const std::string& case_name) { return find_case_entry(case_name).problem; }

nlohmann::json options_json(const std::vector<FamilyOption>& options) {
  nlohmann::json report = nlohmann::json::object();
  for (const FamilyOption& option : options)
    std::visit(
        [&](auto* value) {
          if constexpr (requires { value->has_value(); })
            report[option.name + 2] = optional_json(*value);
          else
            report[option.name + 2] = *value;
        },
        option.value);
  return report;
}

nlohmann::json Family::options_json(const ProblemOptions& o) const {
  ProblemOptions values = o;
  return cli::options_json(options(values));
}

void add_problem_options(CLI::App& app, ProblemOptions& o) {
  for (const Family* family : families())
    for (const FamilyOption& option : family->options(o))
      std::visit(
          [&](auto* value) {
            CLI::Option* bound = app.add_option(option.name, *value, option.help)->group(option.group);
            if constexpr (!requires { value->has_value(); }) bound->capture_default_str();
          },
          option.value);
}

void check_problem_options(const ProblemOptions& o) {
  const Family& own = family_of(o.case_name);
  ProblemOptions values = o, defaults;
  for (const Family* other : families()) {
    if (other == &own) continue;
    const std::vector<FamilyOption> given = other->options(values), unset = other->options(defaults);
    for (std::size_t i = 0; i < given.size(); ++i) {
      const bool set = std::visit(
          [&](auto* value) { return *value != *std::get<decltype(value)>(unset[i].value); }, given[i].value);
      if (set) throw InputError(std::string(given[i].name) + ": applies to " + other->title() + ", not --case " + o.case_name);
    }
  }
}

void validate_problem_options(const ProblemOptions& o) {
  check_problem_options(o);  // the case exists, and no option of another family's cases is set
  for (const Family* family : families()) family->validate(o);
}

nlohmann::json problem_options_json(const ProblemOptions& o) {
  nlohmann::json j = family_of(o.case_name).options_json(o);
  j["case"] = o.case_name;
  return j;
}

void fill_case_defaults(ProblemOptions& o) { family_of(o.case_name).fill_defaults(o); }

bool case_has_closed_form(const ProblemOptions& o) { return family_of(o.case_name).closed_form(o); }

namespace {

// Each family's own schemes (the gas model's temperature updates), for its cases alone.
std::vector<IntegratorEntry> problem_schemes() {
  std::vector<IntegratorEntry> entries;
  for (const Family* family : families())
    for (IntegratorInfo& info : family->integrators()) {
      const std::string name = info.name;
      entries.push_back({std::move(info),
                         [family, name](const std::string&, const IntegratorContext&) { return family->make_integrator(name); },
                         {}, family->title(), {}});
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
  if (const std::optional<IntegratorCatalog::Found> found = study_catalog().find(spec)) return found->entry->info.traits;
  return std::nullopt;
}

IntegratorTraits integrator_traits(const std::string& spec) {
  if (std::optional<IntegratorTraits> traits = find_integrator_traits(spec)) return *traits;
  throw InputError("--integrator", spec, "unknown integrator (see `dlpverify cases`)");
}

std::unique_ptr<Integrator> make_study_integrator(const std::string& name, const CvodeSettings& cvode,
                                                  const std::string& case_name, const exchange::ExecSettings& exec) {
  const std::optional<IntegratorCatalog::Found> found = study_catalog().find(name);
  if (found && !found->entry->family.empty() && found->entry->family != family_of(case_name).title())
    for (const Family* family : families())
      if (family->title() == found->entry->family) {
        std::string cases;
        for (const CaseEntry& c : family->cases()) cases += (cases.empty() ? "" : ", ") + c.name;
        throw InputError("--integrator", name, "integrates " + family->title() + " only; use it with --case " + cases);
      }
  if (found && found->entry->make)
    if (std::unique_ptr<Integrator> integrator = found->entry->make(found->argument, IntegratorContext{cvode, exec, std::nullopt}))
      return integrator;
  // An unknown name, or arkode-erk: with a table ARKODE does not have: refused there, naming it.
  return make_integrator(name, cvode);
}

ProblemSize problem_size(const ProblemOptions& o) { return family_of(o.case_name).size(o); }

std::unique_ptr<Problem> make_problem(const ProblemOptions& o) { return family_of(o.case_name).make(o); }

void check_duration(const ProblemOptions& o, double t_end) { family_of(o.case_name).check_duration(o, t_end); }

BaselineAudit audit_case(const ProblemOptions& o, const std::string& case_name, double t_end) {
  return family_of(case_name).audit(o, case_name, t_end);
}

std::vector<BaselineAudit> audit_all() {
  std::vector<BaselineAudit> audits;
  for (const Family* family : families())
    for (BaselineAudit& audit : family->default_audits()) audits.push_back(std::move(audit));
  // The closed forms first, then the published formulas (expected to fail).
  std::stable_partition(audits.begin(), audits.end(), [](const BaselineAudit& a) { return !a.published; });
  return audits;
}

}  // namespace dlpverify::cli
