// The problems the command line offers, and how options make one: the DLP cloud's cases and the gas
// adiabats' (with the gas's own temperature updates as integrators). The one place outside
// problems/ that knows a problem's own parameters.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "dlpverify/problem.hpp"
#include "exchange/exec_integrator.hpp"
#include "sundials/closed_form_audit.hpp"
#include "sundials/integrators.hpp"

namespace dlpverify::cli {

struct CaseEntry {
  std::string name;
  std::string problem;           // "dlp" (the particle cloud) or "gas" (gas parcels)
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

// The problem a case belongs to, "dlp" or "gas"; throws InputError naming --case for an unknown case.
std::string problem_of_case(const std::string& case_name);
// Refuses an option of another problem's cases set away from its default (it would be ignored).
void check_problem_options(const ProblemOptions& options);
// Fills the case's own defaults into unset options, so that reports show what was run.
void fill_case_defaults(ProblemOptions& options);

// Every integrator: the generic ones, the gas cases' own temperature updates, then exec:COMMAND.
std::vector<IntegratorInfo> known_study_integrators();
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
// Where in the population each member sits, for --per-particle (DLP: ξ at launch; DLP only).
Eigen::ArrayXd member_coordinate(const Problem& problem);

// Refuses input the problem cannot take over the study's duration (DLP: past burn-out; gas: a
// path reaching J ≤ b').
void check_duration(const ProblemOptions& options, double t_end);

// The audit of a case's closed form on these options' physics, over t_end.
BaselineAudit audit_case(const ProblemOptions& options, const std::string& case_name, double t_end);
// Every closed form with default parameters, then the source paper's published formulas.
std::vector<BaselineAudit> audit_all();

}  // namespace dlpverify::cli
