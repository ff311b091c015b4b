#include "cli/problems.hpp"

#include "dlpverify/errors.hpp"
#include "problems/dlp/audit_samples.hpp"
#include "problems/dlp/exact/burn.hpp"
#include "problems/dlp/problem.hpp"

namespace dlpverify::cli {

namespace {

Lattice lattice_of(const ProblemOptions& o, const Case& test_case) {
  Lattice lattice;
  lattice.shape = o.shape == "sphere" ? Shape::sphere : Shape::shell;
  lattice.outer = o.outer;
  lattice.inner = o.inner ? *o.inner : Lattice::default_inner(lattice.shape, o.outer);
  lattice.spacing = o.spacing ? *o.spacing : o.parameters.diameter;
  lattice.z_axis_only = test_case.z_axis_only;
  return lattice;
}

BaselineAudit audit_entry(const std::string& name, bool published, const std::string& source, const Problem& sample,
                          double t_end) {
  BaselineAudit audit = audit_closed_form(sample, t_end);
  audit.baseline = name;
  audit.published = published;
  audit.source = source;
  return audit;
}

}  // namespace

std::vector<CaseEntry> all_cases() {
  std::vector<CaseEntry> entries;
  for (const Case& c : dlpverify::all_cases())
    entries.push_back({c.name, c.summary, describe_terms(c.terms), c.reference_detail, c.solution != nullptr,
                       {c.defaults.t_end, c.defaults.dt, c.defaults.levels}});
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

ProblemSize problem_size(const ProblemOptions& o) {
  return {count_lattice_points(lattice_of(o, find_case(o.case_name))), kFields};
}

std::unique_ptr<Problem> make_problem(const ProblemOptions& o) {
  const Case& test_case = find_case(o.case_name);
  return std::make_unique<DlpProblem>(test_case, o.parameters, lattice_of(o, test_case), Launch{o.expansion_speed});
}

Eigen::ArrayXd member_coordinate(const Problem& problem) {
  return dynamic_cast<const DlpProblem&>(problem).similarity_coordinate();
}

void check_duration(const ProblemOptions& o, double t_end) {
  if (find_case(o.case_name).terms.burning) exact::check_before_burn_out(o.parameters, t_end);
}

BaselineAudit audit_case(const ProblemOptions& o, const std::string& case_name, double t_end) {
  const Case& test_case = find_case(case_name);
  return audit_entry(test_case.name, false, test_case.reference_detail, *audit_sample(test_case, o.parameters), t_end);
}

std::vector<BaselineAudit> audit_all() {
  std::vector<BaselineAudit> audits;
  const Parameters defaults;
  for (const Case& c : dlpverify::all_cases())
    if (c.solution != nullptr)
      audits.push_back(audit_entry(c.name, false, c.reference_detail, *audit_sample(c, defaults), c.defaults.t_end));
  for (const PublishedFormula& formula : published_formulas(defaults))
    audits.push_back(audit_entry(formula.name, true, formula.source, *formula.sample, 0.01));
  return audits;
}

}  // namespace dlpverify::cli
