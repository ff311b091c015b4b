#include "cli/problems.hpp"

#include <algorithm>
#include <iostream>

#include "cli/family.hpp"
#include "dlpverify/errors.hpp"
#include "exchange/exchange_file.hpp"
#include "integrators/implicit/integrators.hpp"
#include "integrators/tableau/tableau_integrator.hpp"
#include "problems/dlp/problem.hpp"

namespace dlpverify::cli {

using namespace dlp;  // the DLP cloud's types

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

void add_problem_options(CLI::App& app, ProblemOptions& o) {
  for (const Family* family : families()) family->add_options(app, o);
}

void check_problem_options(const ProblemOptions& o) {
  const Family& own = family_of(o.case_name);
  for (const Family* other : families()) {
    if (other == &own) continue;
    for (const auto& [option, set] : other->options_set(o))
      if (set) throw InputError(std::string(option) + ": applies to " + other->title() + ", not --case " + o.case_name);
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

std::vector<IntegratorInfo> known_study_integrators() {
  std::vector<IntegratorInfo> list = known_integrators();
  for (IntegratorInfo& info : implicit::implicit_integrators()) list.push_back(std::move(info));
  for (const Family* family : families())
    for (IntegratorInfo& info : family->integrators()) list.push_back(std::move(info));
  IntegratorTraits program;  // steps by its own equations, its own steps, swept by {rtol}
  program.calls_problem_rhs = false;
  program.tolerance_driven = true;
  program.runs_program = true;
  list.push_back({"exec:COMMAND", 0, "your own program, run per level on an HDF5 file (docs/exchange.md); --exec-order P",
                  program, true});
  list.push_back({"tableau:FILE", 0, "your own explicit Butcher tableau from a TOML file, at the file's order (dlpverify tableau FILE)",
                  runge_kutta_traits(), true});
  return list;
}

std::optional<IntegratorTraits> find_integrator_traits(const std::string& spec) {
  for (const std::vector<IntegratorInfo>& list : {known_study_integrators(), adaptive_integrators()})
    for (const IntegratorInfo& info : list) {
      const std::string prefix = info.pattern ? info.name.substr(0, info.name.find(':') + 1) : info.name;
      if (info.pattern ? spec.rfind(prefix, 0) == 0 : spec == info.name) return info.traits;
    }
  return std::nullopt;
}

IntegratorTraits integrator_traits(const std::string& spec) {
  if (std::optional<IntegratorTraits> traits = find_integrator_traits(spec)) return *traits;
  throw InputError("--integrator", spec, "unknown integrator (see `dlpverify cases`)");
}

std::unique_ptr<Integrator> make_study_integrator(const std::string& name, const CvodeSettings& cvode,
                                                  const std::string& case_name, const exchange::ExecSettings& exec) {
  if (name.rfind(exchange::kExecPrefix, 0) == 0) {
    exchange::ExecSettings settings = exec;
    settings.command = name.substr(std::string(exchange::kExecPrefix).size());
    try {
      return std::make_unique<exchange::ExecIntegrator>(settings);
    } catch (const exchange::ExchangeError& e) {
      throw InputError("--integrator", name, e.what());
    }
  }
  if (name.rfind(kTableauPrefix, 0) == 0)
    return make_tableau_integrator(name.substr(std::string(kTableauPrefix).size()), std::cerr);
  const Family& own = family_of(case_name);
  for (const Family* family : families()) {
    std::unique_ptr<Integrator> integrator = family->make_integrator(name);
    if (!integrator) continue;
    if (family != &own) {
      std::string cases;
      for (const CaseEntry& c : family->cases()) cases += (cases.empty() ? "" : ", ") + c.name;
      throw InputError("--integrator", name, "integrates " + family->title() + " only; use it with --case " + cases);
    }
    return integrator;
  }
  if (std::unique_ptr<Integrator> integrator = implicit::make_implicit_integrator(name)) return integrator;
  return make_integrator(name, cvode);
}

ProblemSize problem_size(const ProblemOptions& o) { return family_of(o.case_name).size(o); }

std::unique_ptr<Problem> make_problem(const ProblemOptions& o) { return family_of(o.case_name).make(o); }

Eigen::ArrayXd member_coordinate(const Problem& problem) {
  return dynamic_cast<const DlpProblem&>(problem).similarity_coordinate();
}

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
