#include "problems/dlp/diagnostics.hpp"

#include <cmath>
#include <string>

#include "problems/dlp/exact/vertical_drag_gravity.hpp"
#include "problems/dlp/kinetic_energy.hpp"

namespace dlpverify::dlp::diagnostics {

nlohmann::json similarity_energy(const DiagnosticsInput& input) {
  const double launch_energy = kinetic_energy(input.initial);
  const double final_energy = kinetic_energy(input.finest);
  return {{"kinetic_energy_t0", launch_energy},
          {"kinetic_energy_end", final_energy},
          {"kinetic_energy_relative_change", (final_energy - launch_energy) / launch_energy},
          {"kinetic_energy_over_0.3_M_us2", similarity_energy_ratio(input.initial, input.launch)}};
}

nlohmann::json vertical_branches(const DiagnosticsInput& input) {
  int counts[exact::kVerticalBranches] = {};
  for (Eigen::Index p = 0; p < input.initial.size(); ++p)
    ++counts[static_cast<int>(exact::vertical_branch(input.physics, input.initial.particle(p), input.t_end))];
  nlohmann::json branches = nlohmann::json::object();
  for (int b = 0; b < exact::kVerticalBranches; ++b)
    branches[std::string(exact::to_string(static_cast<exact::VerticalBranch>(b)))] = counts[b];
  // docs/model.md §4.4: a case that uses this baseline must take particles through all three branches,
  // rising through the apex, falling slower and falling faster than v_t.
  const bool every_branch = counts[static_cast<int>(exact::VerticalBranch::rising_through_apex)] > 0 &&
                            counts[static_cast<int>(exact::VerticalBranch::falling_slower)] > 0 &&
                            counts[static_cast<int>(exact::VerticalBranch::falling_faster)] > 0;
  return {{"particles_per_branch", branches},
          {"every_branch_taken", every_branch},
          {"terminal_speed", exact::terminal_speed(input.physics.parameters)},
          {"drag_gravity_time", exact::drag_gravity_time(input.physics.parameters)}};
}

}  // namespace dlpverify::dlp::diagnostics
