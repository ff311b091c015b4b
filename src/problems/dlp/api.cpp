// The installed entry to the DLP problem (include/dlpverify/dlp.hpp).
#include "dlpverify/dlp.hpp"

#include "problems/dlp/problem.hpp"

namespace dlpverify::dlp {

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const Case& c : all_cases()) names.push_back(c.name);
  return names;
}

StudyDefaults case_defaults(const std::string& case_name) {
  const CaseDefaults& d = find_case(case_name).defaults;
  return {d.t_end, d.dt, d.levels};
}

std::unique_ptr<Problem> make_problem(const std::string& case_name, const CloudShape& cloud) {
  const Case& test_case = find_case(case_name);
  const Parameters parameters;
  Lattice lattice;
  lattice.shape = cloud.shell ? Shape::shell : Shape::sphere;
  lattice.outer = cloud.outer;
  lattice.inner = Lattice::default_inner(lattice.shape, cloud.outer);
  lattice.spacing = parameters.diameter;
  lattice.z_axis_only = test_case.z_axis_only;
  return std::make_unique<DlpProblem>(test_case, parameters, lattice, Launch{cloud.expansion_speed});
}

}  // namespace dlpverify::dlp
