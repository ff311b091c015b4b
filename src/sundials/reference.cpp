#include "sundials/reference.hpp"

#include <chrono>
#include <algorithm>
#include <cstdio>
#include <exception>

#include "problems/dlp/exact/burn.hpp"
#include "problems/dlp/exact/cloud_solution.hpp"
#include "io/errors.hpp"

namespace dlpverify {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Particles do not interact, so the reference solves blocks of kReferenceBlock particles, each
// with its own CVODE, one solver per thread. A block's vectors (64 KB each) stay in cache, where a
// whole-cloud vector streams from memory: CVODE's Adams predictor sweeps its ~q²/2 Nordsieck
// vectors every step, which on the seed sphere (268 MB per vector) took 1.7 s a step. Each block
// also gets its own error control, at least as tight as one over the whole cloud.
constexpr Eigen::Index kReferenceBlock = 1024;

// CVODE Adams (the problems are non-stiff; its step sequence is also the most reproducible) from
// t0 to t0 + t_end with no step limit but t_end itself, and absolute tolerances scaled by the
// whole cloud's field sizes so every block is held to the same standard.
Cloud solve_with_cvode(const Physics& physics, const Cloud& initial, double t0, double t_end, double rtol,
                       const ReferenceSettings& settings, nlohmann::json& statistics) {
  CvodeSettings cvode;
  cvode.rtol = rtol;
  cvode.atol = absolute_tolerances(initial, rtol);
  cvode.method = CvodeMethod::adams;
  cvode.max_steps = settings.max_steps;
  cvode.openmp_vector = false;  // the threads share out blocks instead
  const ParticleRates rates(physics);

  const Eigen::Index particles = initial.size();
  const Eigen::Index blocks = (particles + kReferenceBlock - 1) / kReferenceBlock;
  Cloud result(particles);
  long steps_max = 0, steps_total = 0, rhs_evals_total = 0;
  std::exception_ptr failure;
#pragma omp parallel
  {
    CvodeIntegrator integrator(cvode);
    Cloud block;
#pragma omp for schedule(dynamic)
    for (Eigen::Index b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * kReferenceBlock;
      const Eigen::Index count = std::min(kReferenceBlock, particles - first);
      if (block.size() != count) block = Cloud(count);
      block.state() = initial.state().middleRows(first, count);
      try {
        integrator.advance(rates, block, t0, t_end, 1);
      } catch (...) {
#pragma omp critical(dlpverify_reference_failure)
        if (!failure) failure = std::current_exception();
        continue;
      }
      result.state().middleRows(first, count) = block.state();
      const nlohmann::json counts = integrator.statistics();
#pragma omp critical(dlpverify_reference_statistics)
      {
        steps_max = std::max(steps_max, counts.value("steps", 0L));
        steps_total += counts.value("steps", 0L);
        rhs_evals_total += counts.value("rhs_evals", 0L);
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
  statistics = {{"method", "adams"},          {"rtol", rtol},
                {"blocks", blocks},           {"particles_per_block", kReferenceBlock},
                {"steps_max", steps_max},     {"steps_total", steps_total},
                {"rhs_evals_total", rhs_evals_total}};
  return result;
}

}  // namespace

Reference compute_reference(const Case& test_case, const ReferenceSettings& settings, const Physics& physics,
                            const Cloud& initial, double t0, double t_end, const std::vector<VariableGroup>& variables) {
  // Past burn-out the mass equation has no meaning (and exact::burn throws, which it must not do
  // inside the OpenMP loop of exact::evaluate): refuse it here, as input.
  if (physics.terms.burning) exact::check_before_burn_out(physics.parameters, t_end);
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

std::function<Cloud(double tau)> reference_trajectory(const Case& test_case, const ReferenceSettings& settings,
                                                      const Physics& physics, const Cloud& initial, double t0) {
  if (settings.kind == ReferenceKind::exact) {
    if (test_case.solution == nullptr)
      throw InputError("--reference", "exact", "case " + test_case.name + " has no closed form; use --reference cvode");
    return [solution = test_case.solution, physics, &initial](double tau) {
      return exact::evaluate(solution, physics, initial, tau);
    };
  }
  struct Continued {
    Cloud state;
    double tau = 0.0;
  };
  auto last = std::make_shared<Continued>(Continued{initial, 0.0});
  return [last, physics, settings, t0](double tau) {
    if (tau > last->tau) {
      nlohmann::json ignored;
      last->state = solve_with_cvode(physics, last->state, t0 + last->tau, tau - last->tau, settings.rtol, settings, ignored);
      last->tau = tau;
    }
    return last->state;
  };
}

}  // namespace dlpverify
