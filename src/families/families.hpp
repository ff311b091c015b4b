// The problem families a study can name a case of (the DLP cloud, the gas adiabats, the thermal
// cases), and how a case's options make its problem. Each question about a case goes to the family
// the case belongs to (families/family.hpp): the one place outside problems/ that knows a
// problem's own parameters.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"
#include "families/problem_options.hpp"
#include "references/closed_form_audit.hpp"

namespace dlpverify::dlp {
class DlpProblem;
}

namespace dlpverify::families {

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
// The case of that name; throws InputError naming the case otherwise.
const CaseEntry& find_case_entry(const std::string& name);

// The problem family a case belongs to ("dlp", "gas", …); throws InputError naming the case for an
// unknown case.
std::string problem_of_case(const std::string& case_name);
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
// The DLP cloud of validated options as its own type: the kernels' benchmark switches the path of
// its right-hand side.
std::unique_ptr<dlp::DlpProblem> make_dlp_problem(const ProblemOptions& options);

// Refuses input the problem cannot take over the study's duration (DLP: past burn-out; gas: a
// path reaching J ≤ b').
void check_duration(const ProblemOptions& options, double t_end);

// Refuses a study whose `copies` of the state do not fit in the memory the machine can still give
// (InputError naming the option that sets the member count, with the estimate and what is
// available). Under mpirun each rank checks its share, and rank 0 two whole states beside when
// the per-member errors are `gathered`.
void check_memory(const ProblemOptions& options, int copies, bool gathered);

// docs/model.md §4: a closed form is trusted only after its audit passes on this study's physics
// over t_end; otherwise InputError naming the case.
void require_audited_closed_form(const ProblemOptions& options, double t_end);

// The audit of a case's closed form on these options' physics, over t_end.
BaselineAudit audit_case(const ProblemOptions& options, const std::string& case_name, double t_end);
// Every closed form with default parameters, then the source paper's published formulas.
std::vector<BaselineAudit> audit_all();

}  // namespace dlpverify::families
