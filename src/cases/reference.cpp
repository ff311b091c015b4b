#include "cases/reference.hpp"

#include <chrono>
#include <cstdio>

#include "exact/cloud_solution.hpp"
#include "io/errors.hpp"

namespace dlpverify {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CVODE Adams (the problems are non-stiff; its step sequence is also the most reproducible) from
// t0 to t0 + t_end with no step limit but t_end itself.
Cloud solve_with_cvode(const Physics& physics, const Cloud& initial, double t0, double t_end, double rtol,
                       const ReferenceSettings& settings, nlohmann::json& statistics) {
  CvodeSettings cvode;
  cvode.rtol = rtol;
  cvode.atol = absolute_tolerances(initial, rtol);
  cvode.method = CvodeMethod::adams;
  cvode.max_steps = settings.max_steps;
  cvode.openmp_vector = settings.openmp_vector;
  CvodeIntegrator integrator(cvode);
  Cloud state = initial;
  integrator.advance(ParticleRates(physics), state, t0, t_end, 1);
  statistics = integrator.statistics();
  return state;
}

}  // namespace

Reference compute_reference(const Case& test_case, const ReferenceSettings& settings, const Physics& physics,
                            const Cloud& initial, double t0, double t_end, const std::vector<VariableGroup>& variables) {
  Reference reference;
  const auto start = std::chrono::steady_clock::now();
  if (settings.kind == ReferenceKind::exact) {
    if (test_case.solution == nullptr)
      throw InputError("--reference", "exact", "case " + test_case.name + " has no closed form; use --reference cvode");
    reference.state = exact::evaluate(test_case.solution, physics, initial, t_end);
    reference.kind = "exact";
    reference.detail = test_case.reference_detail;
    reference.error_estimate.assign(variables.size(), 0.0);
    reference.statistics = {{"wall_s", seconds_since(start)}};
    return reference;
  }

  nlohmann::json first, second;
  reference.state = solve_with_cvode(physics, initial, t0, t_end, settings.rtol, settings, first);
  const double first_seconds = seconds_since(start);
  const Cloud tighter = solve_with_cvode(physics, initial, t0, t_end, settings.rtol / 10.0, settings, second);
  for (const VariableGroup& v : variables)
    reference.error_estimate.push_back(error_norms(reference.state.state(), tighter.state(), v).l2);

  char detail[160];
  std::snprintf(detail, sizeof detail, "CVODE Adams, rtol %.0e, atol rtol x field scale; error estimated against rtol %.0e",
                settings.rtol, settings.rtol / 10.0);
  reference.kind = "cvode";
  reference.detail = detail;
  reference.statistics = {{"rtol", settings.rtol},
                          {"wall_s", first_seconds},
                          {"solve", first},
                          {"error_estimate_solve", second},
                          {"error_estimate_wall_s", seconds_since(start) - first_seconds}};
  return reference;
}

}  // namespace dlpverify
