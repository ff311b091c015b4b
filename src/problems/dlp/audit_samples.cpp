#include "problems/dlp/audit_samples.hpp"

#include "problems/dlp/exact/published.hpp"

namespace dlpverify::dlp {

namespace {
Lattice sample_lattice(bool z_axis_only, const Parameters& parameters) {
  Lattice lattice;
  lattice.shape = Shape::sphere;
  lattice.outer = z_axis_only ? 100 : 4;
  lattice.inner = 0;
  lattice.spacing = parameters.diameter;
  lattice.z_axis_only = z_axis_only;
  return lattice;
}
}  // namespace

std::unique_ptr<DlpProblem> audit_sample(const Case& test_case, const Parameters& parameters) {
  return std::make_unique<DlpProblem>(test_case, parameters, sample_lattice(test_case.z_axis_only, parameters),
                                      Launch{100.0});
}

std::vector<PublishedFormula> published_formulas(const Parameters& parameters) {
  const Lattice lattice = sample_lattice(false, parameters);
  const Launch launch{100.0};
  auto sample = [&](const char* case_name, exact::ParticleSolution solution, const char* detail) {
    return std::make_unique<DlpProblem>(find_case(case_name), parameters, make_cloud(lattice, launch, parameters),
                                        initial_time(lattice, launch), solution, detail);
  };
  std::vector<PublishedFormula> formulas;
  formulas.push_back({"Kuhl & Grote eq. 23", "v = -K v0 i / ((t0 - t) v0 + 1): dimensionally wrong",
                      sample("drag", &exact::seed_drag_eq23, "Kuhl & Grote eq. 23")});
  formulas.push_back({"Kuhl & Grote eq. 26", "eq. 23 + v0 + (i.g) t: superposes a nonlinear ODE",
                      sample("drag-gravity", &exact::seed_complete_eq26, "Kuhl & Grote eq. 26")});
  return formulas;
}

}  // namespace dlpverify::dlp
