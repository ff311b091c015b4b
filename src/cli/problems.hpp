// The problems the command line offers, and how options make one. The one place outside
// problems/ that knows a problem's own parameters (today the DLP cloud's).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "dlpverify/problem.hpp"
#include "sundials/closed_form_audit.hpp"

namespace dlpverify::cli {

struct CaseEntry {
  std::string name;
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

// The size of the study's state, members × fields, without building the problem (for the memory
// estimate: DLP counts its lattice column by column).
struct ProblemSize {
  long long members = 0;
  int fields = 0;
};
ProblemSize problem_size(const ProblemOptions& options);

// The study's problem, from validated options with the case's defaults filled in.
std::unique_ptr<Problem> make_problem(const ProblemOptions& options);
// Where in the population each member sits, for --per-particle (DLP: ξ at launch).
Eigen::ArrayXd member_coordinate(const Problem& problem);

// Refuses input the problem cannot take over the study's duration (DLP: past burn-out).
void check_duration(const ProblemOptions& options, double t_end);

// The audit of a case's closed form on these options' physics, over t_end.
BaselineAudit audit_case(const ProblemOptions& options, const std::string& case_name, double t_end);
// Every closed form with default parameters, then the source paper's published formulas.
std::vector<BaselineAudit> audit_all();

}  // namespace dlpverify::cli
