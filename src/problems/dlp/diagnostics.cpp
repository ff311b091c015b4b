#include "problems/dlp/diagnostics.hpp"

#include <string>

#include "problems/dlp/exact/vertical_drag_gravity.hpp"
#include "problems/dlp/kinetic_energy.hpp"

namespace dlpverify::dlp::diagnostics {

namespace {

// Each particle's ½ m v² at launch and at the end, and its mass.
Eigen::ArrayXXd energy_terms(const DiagnosticsInput& input) {
  Eigen::ArrayXXd terms(input.initial.size(), 3);
  for (Eigen::Index p = 0; p < input.initial.size(); ++p) {
    terms(p, 0) = particle_kinetic_energy(input.initial.state(), p);
    terms(p, 1) = particle_kinetic_energy(input.finest.state(), p);
    terms(p, 2) = input.initial.state()(p, MASS);
  }
  return terms;
}

nlohmann::json energy_report(const Physics&, const Launch& launch, const std::vector<double>& reduced, double) {
  const double launch_energy = reduced[0], final_energy = reduced[1], total_mass = reduced[2];
  return {{"kinetic_energy_t0", launch_energy},
          {"kinetic_energy_end", final_energy},
          {"kinetic_energy_relative_change", (final_energy - launch_energy) / launch_energy},
          {"kinetic_energy_over_0.3_M_us2", similarity_energy_ratio(launch_energy, total_mass, launch)}};
}

// Each particle's branch as a 1 in its branch's column.
Eigen::ArrayXXd branch_terms(const DiagnosticsInput& input) {
  Eigen::ArrayXXd terms = Eigen::ArrayXXd::Zero(input.initial.size(), exact::kVerticalBranches);
  for (Eigen::Index p = 0; p < input.initial.size(); ++p)
    terms(p, static_cast<int>(exact::vertical_branch(input.physics, input.initial.particle(p), input.t_end))) = 1.0;
  return terms;
}

nlohmann::json branch_report(const Physics& physics, const Launch&, const std::vector<double>& reduced, double) {
  const auto count = [&reduced](exact::VerticalBranch b) { return static_cast<long>(reduced[static_cast<std::size_t>(b)]); };
  nlohmann::json branches = nlohmann::json::object();
  for (int b = 0; b < exact::kVerticalBranches; ++b) {
    const auto branch = static_cast<exact::VerticalBranch>(b);
    branches[std::string(exact::to_string(branch))] = count(branch);
  }
  // docs/model.md §4.4: a case that uses this baseline must take particles through all three branches,
  // rising through the apex, falling slower and falling faster than v_t.
  const bool every_branch = count(exact::VerticalBranch::rising_through_apex) > 0 &&
                            count(exact::VerticalBranch::falling_slower) > 0 &&
                            count(exact::VerticalBranch::falling_faster) > 0;
  return {{"particles_per_branch", branches},
          {"every_branch_taken", every_branch},
          {"terminal_speed", exact::terminal_speed(physics.parameters)},
          {"drag_gravity_time", exact::drag_gravity_time(physics.parameters)}};
}

}  // namespace

const CaseDiagnostics similarity_energy{
    {MemberReduction::sum, MemberReduction::sum, MemberReduction::sum}, &energy_terms, &energy_report};

const CaseDiagnostics vertical_branches{
    std::vector<MemberReduction>(exact::kVerticalBranches, MemberReduction::sum), &branch_terms, &branch_report};

}  // namespace dlpverify::dlp::diagnostics
