// A family of problems as a study is given them: its cases, its own options (declared once: bound
// by the command line, checked, reported), the defaults its cases fill in, how options make its
// problem, its audits, and the integrators of its own. families/families.cpp answers every
// question about a case by asking the family the case belongs to, so a new family is one more
// file in src/families and two lines in families.cpp (its NAME_family() declared, and listed).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/integrator.hpp"
#include "families/families.hpp"
#include "families/problem_options.hpp"
#include "integrators/registry.hpp"

namespace dlpverify::families {

// One option of a family: its name (--NAME on the command line; NAME keys it in the report), its
// help and group, and the value it sets. An optional value is unset by default (its help names
// the default); every other shows its default in the help.
struct FamilyOption {
  const char* name;
  std::string help;
  std::string group;
  std::variant<int*, double*, std::string*, std::optional<int>*, std::optional<double>*, std::optional<std::string>*> value;
};
// The report of `options` ({"outer": 100, "inner": null, …}).
nlohmann::json options_json(const std::vector<FamilyOption>& options);

class Family {
 public:
  virtual ~Family() = default;
  virtual std::string name() const = 0;   // "dlp", "gas", …: CaseEntry::problem
  virtual std::string title() const = 0;  // "the DLP cloud's cases", for messages
  virtual std::vector<CaseEntry> cases() const = 0;

  // The family's options, each declared once, with `o`'s values (the command binds them, another
  // family's case refuses one set away from its default, the report lists them).
  virtual std::vector<FamilyOption> options(ProblemOptions& o) const = 0;
  // Refuses a value of the family's options outside its domain (InputError naming the option).
  virtual void validate(const ProblemOptions& o) const = 0;
  // The family's options for the report (default: every one of options()).
  virtual nlohmann::json options_json(const ProblemOptions& o) const;
  // Fills the case's own defaults into unset options.
  virtual void fill_defaults(ProblemOptions& /*o*/) const {}

  // Whether the case has a closed form on these options' physics (default: the case's entry).
  virtual bool closed_form(const ProblemOptions& o) const;
  virtual ProblemSize size(const ProblemOptions& o) const = 0;
  virtual std::unique_ptr<Problem> make(const ProblemOptions& o) const = 0;
  virtual void check_duration(const ProblemOptions& /*o*/, double /*t_end*/) const {}

  // The audit of a case's closed form on these options, and every closed form's with defaults.
  virtual BaselineAudit audit(const ProblemOptions& o, const std::string& case_name, double t_end) const = 0;
  virtual std::vector<BaselineAudit> default_audits() const = 0;

  // The family's own integrators (they refuse other families' problems), and one by name or nullptr.
  virtual std::vector<IntegratorInfo> integrators() const { return {}; }
  virtual std::unique_ptr<Integrator> make_integrator(const std::string& /*name*/) const { return nullptr; }
};

// The families, in the order `dlpverify cases` lists them.
const std::vector<const Family*>& families();
// The family of a case; throws InputError naming --case for an unknown case.
const Family& family_of(const std::string& case_name);

// An audit entry named for its case (or formula), with its source.
BaselineAudit named_audit(const std::string& name, bool published, const std::string& source, const Problem& sample,
                          double t_end);

}  // namespace dlpverify::families
