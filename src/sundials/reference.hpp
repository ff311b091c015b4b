// The reference a study measures every level against, computed once per study (never per level):
// the case's closed form, or CVODE at a tight tolerance where there is none (SPEC §4).
//
// A CVODE reference carries an estimate of its own error: a second solve at rtol/10, compared
// with the first, variable by variable (L2 over the cloud). The harness then refuses to trust a
// study whose finest level is not at least 100× more wrong than the reference.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "problems/dlp/case.hpp"
#include "harness/norms.hpp"
#include "sundials/cvode_integrator.hpp"

namespace dlpverify {

enum class ReferenceKind { exact, cvode };

struct ReferenceSettings {
  ReferenceKind kind = ReferenceKind::exact;
  double rtol = 1e-12;          // CVODE reference; absolute tolerances scale per field
  long max_steps = 100000;   // per solve
  bool openmp_vector = false;
};

struct Reference {
  Cloud state;                        // at t0 + t_end
  std::string kind;                   // "exact" | "cvode"
  std::string detail;
  std::vector<double> error_estimate; // per measured variable; 0 for a closed form (round-off only)
  nlohmann::json statistics = nlohmann::json::object();  // solver counts and wall time
};

// Throws InputError naming --reference when the case has no closed form and exact was asked for.
Reference compute_reference(const Case& test_case, const ReferenceSettings& settings, const Physics& physics,
                            const Cloud& initial, double t0, double t_end, const std::vector<VariableGroup>& variables);

// The reference at increasing times τ (for error histories): the closed form from the launch
// state, or CVODE continued from the previous time with the settings of compute_reference.
std::function<Cloud(double tau)> reference_trajectory(const Case& test_case, const ReferenceSettings& settings,
                                                      const Physics& physics, const Cloud& initial, double t0);

}  // namespace dlpverify
