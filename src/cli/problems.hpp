// The problems the command line offers, and how options make one. Each question about a case goes
// to the family the case belongs to (cli/family.hpp: the DLP cloud, the gas adiabats, …): the one
// place outside problems/ that knows a problem's own parameters.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/options.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"
#include "integrators/exec/exec_integrator.hpp"
#include "references/closed_form_audit.hpp"
#include "integrators/catalog.hpp"
#include "integrators/registry.hpp"

namespace dlpverify::cli {

struct CaseEntry {
  std::string name;
  std::string problem;           // its family: "dlp" (the particle cloud), "gas" (gas parcels), …
  std::string summary;
  std::string terms;             // what the case switches on
  std::string reference_detail;  // its closed form, or why there is none
  bool closed_form = false;
  StudyDefaults defaults;
};

// Every case of every problem, in the order `dlpverify cases` lists them.
std::vector<CaseEntry> all_cases();
// The case of that name; throws InputError naming --case otherwise.
const CaseEntry& find_case_entry(const std::string& name);

// The problem family a case belongs to ("dlp", "gas", …); throws InputError naming --case for an
// unknown case.
std::string problem_of_case(const std::string& case_name);
// Binds every family's options to a study command.
void add_problem_options(CLI::App& app, ProblemOptions& options);
// Refuses an option of another family's cases set away from its default (it would be ignored).
void check_problem_options(const ProblemOptions& options);
// check_problem_options, then every family's domain checks.
void validate_problem_options(const ProblemOptions& options);
// The case and the options of its family only (the others do not apply to it), for the report.
nlohmann::json problem_options_json(const ProblemOptions& options);
// Fills the case's own defaults into unset options, so that reports show what was run.
void fill_case_defaults(ProblemOptions& options);
// Whether the case has a closed form with these options' physics.
bool case_has_closed_form(const ProblemOptions& options);

// Every integrator: the explicit and SUNDIALS ones, the implicit ones, each family's own, then
// exec:COMMAND.
std::vector<IntegratorInfo> known_study_integrators();

// Every integrator a study can name (integrators/catalog.hpp), each family's own schemes included.
const IntegratorCatalog& study_catalog();

// The traits of the entry of study_catalog() that `spec` names (a pattern entry's prefix for
// exec:COMMAND and tableau:FILE); nullopt, or InputError naming --integrator, for none.
std::optional<IntegratorTraits> find_integrator_traits(const std::string& spec);
IntegratorTraits integrator_traits(const std::string& spec);
// The integrator of that name for a study of `case_name`; throws InputError naming --integrator
// for an unknown one, or a problem's own integrator given with another problem's case. `exec`
// configures an exec:COMMAND integrator (its command is the name's rest).
std::unique_ptr<Integrator> make_study_integrator(const std::string& name, const CvodeSettings& cvode,
                                                  const std::string& case_name,
                                                  const exchange::ExecSettings& exec = {});

// The size of the study's state, members × columns, without building the problem (for the memory
// estimate: DLP counts its lattice column by column), and the option that sets the member count.
struct ProblemSize {
  long long members = 0;
  int fields = 0;      // the wider of the state and its measured copy (gas: T, and P beside it)
  std::string option;  // --outer, --parcels
  std::string value;
};
ProblemSize problem_size(const ProblemOptions& options);

// The study's problem, from validated options with the case's defaults filled in.
std::unique_ptr<Problem> make_problem(const ProblemOptions& options);

// Refuses input the problem cannot take over the study's duration (DLP: past burn-out; gas: a
// path reaching J ≤ b').
void check_duration(const ProblemOptions& options, double t_end);

// The audit of a case's closed form on these options' physics, over t_end.
BaselineAudit audit_case(const ProblemOptions& options, const std::string& case_name, double t_end);
// Every closed form with default parameters, then the source paper's published formulas.
std::vector<BaselineAudit> audit_all();

}  // namespace dlpverify::cli
