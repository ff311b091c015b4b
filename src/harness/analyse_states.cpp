// A study of states computed elsewhere: the levels measured and analysed as run_study does.
#include <optional>

#include "dlpverify/errors.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

StudyResult analyse_states(StudyPlan plan, const std::vector<State>& states, const State* reference,
                           const std::vector<double>& reference_error) {
  if (static_cast<std::size_t>(plan.levels) != states.size())
    throw InputError("levels", std::to_string(plan.levels), "there are " + std::to_string(states.size()) + " states");
  const std::vector<long> steps = level_steps(plan);
  StudyResult result;
  result.against_next_level = reference == nullptr;
  if (result.against_next_level) --plan.levels;  // the finest state is the last level's reference
  result.plan = plan;
  for (int k = 0; k < plan.levels; ++k) {
    const State& against = reference ? *reference : states[static_cast<std::size_t>(k) + 1];
    result.levels.push_back(measure_level(plan, k, steps[static_cast<std::size_t>(k)], states[static_cast<std::size_t>(k)],
                                          against, k == 0 ? nullptr : &states[static_cast<std::size_t>(k) - 1]));
  }
  result.finest = states[static_cast<std::size_t>(plan.levels) - 1];
  analyse_levels(result, reference ? reference_error : std::vector<double>{});
  if (reference) return result;
  // Self-convergence over every state, the finest too: d_k = ‖y_{k−1} − y_k‖ is level k − 1's norm,
  // and the Richardson estimate and GCI are the finest state's.
  for (std::size_t v = 0; v < plan.variables.size(); ++v) {
    std::vector<std::optional<double>> differences{std::nullopt};
    for (const LevelResult& level : result.levels) differences.push_back(level.norms[v].l2);
    const double finest_size = result.levels.back().norms[v].reference_l2;  // ‖y‖ of the finest state
    result.self_convergence[v] = analyse_self_convergence(differences, finest_size, plan.ratio);
  }
  return result;
}

}  // namespace dlpverify
