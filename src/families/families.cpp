#include "families/families.hpp"

#include <algorithm>
#include <cstdio>
#include <variant>

#include "dlpverify/errors.hpp"
#include "families/family.hpp"
#include "harness/distribution.hpp"
#include "io/memory.hpp"
#include "io/value_checks.hpp"

namespace dlpverify::families {

// Each family's one object, defined in its own file (src/families/NAME.cpp).
const Family& dlp_family();
const Family& gas_family();
const Family& thermal_family();

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
  throw InputError("case", name, "unknown case (known: " + names + ")");
}

const Family& family_of(const std::string& case_name) {
  const std::string& problem = find_case_entry(case_name).problem;
  for (const Family* family : families())
    if (family->name() == problem) return *family;
  throw InputError("case", case_name, "belongs to no problem family");  // unreachable: entries come from families
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
  return families::options_json(options(values));
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


// Under mpirun (docs/mpi.md) each rank's peak is the copies of its share of the members (every
// problem builds a rank's members alone, dlpverify/initial_members.hpp), and on rank 0, when the
// per-particle errors are asked for (`gathered`), the two whole states they need: the finest
// state and the reference it gathers. The case's diagnostics are reduced from each rank's share.
void check_memory(const ProblemOptions& o, int copies, bool gathered) {
  const ProblemSize size = problem_size(o);
  const double state = static_cast<double>(size.members) * size.fields * sizeof(double);
  double needed = copies * state;
  std::string what = std::to_string(copies) + " copies of the " + std::to_string(size.members) + " x " +
                     std::to_string(size.fields) + " state, " + byte_text(state) + " each";
  if (distribution().ranks() > 1) {
    const Eigen::Index share = own_members(size.members).count;
    const int whole = distribution().rank() == 0 && gathered ? 2 : 0;
    needed = copies * static_cast<double>(share) * size.fields * sizeof(double) + whole * state;
    what = "on rank " + std::to_string(distribution().rank()) + ": " + std::to_string(copies) + " copies of its " +
           std::to_string(share) + " members' state";
    if (whole > 0) what += " and " + std::to_string(whole) + " of the whole, " + byte_text(state);
  }
  const AvailableMemory available = available_memory();
  if (needed <= static_cast<double>(available.bytes)) return;
  throw InputError(size.option, size.value,
                   "the study needs about " + byte_text(needed) + " of memory (" + what + ") but " +
                       byte_text(static_cast<double>(available.bytes)) + " is available (" + available.source + ")");
}

void require_audited_closed_form(const ProblemOptions& o, double t_end) {
  const BaselineAudit audit = audit_case(o, o.case_name, t_end);
  if (audit.passed) return;
  char why[256];
  std::snprintf(why, sizeof why,
                "its closed form failed the audit (ODE residual %.2e, CVODE distance %.2e, %d non-finite; "
                "limits 1e-8, 1e-9): refusing it as a reference (see dlpverify audit)",
                audit.residual, audit.cvode_distance, audit.non_finite);
  throw InputError("case", o.case_name, why);
}

}  // namespace dlpverify::families
