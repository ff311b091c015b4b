// Refinement beyond the reference's trust by the differences between successive levels
// (docs/verification.md, "An order extrapolated from the differences between successive levels").
#include <algorithm>
#include <chrono>

#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"
#include "harness/search_phases.hpp"
#include "io/format.hpp"

namespace dlpverify::search_phase {

namespace {

// A self-difference within this factor of its level's round-off floor (½ ε √n ‖y‖,
// round_off_floor) is rounding as much as convergence: it and finer ones are not used. Above it,
// rounding that bends the pairwise orders breaks their geometric pattern and the extrapolation
// refuses. (RK4 on cooling, 20 particles: 2.0e-10 K at 0.3125 ms, 20 x its floor, orders still
// converging geometrically, measured.)
constexpr double kSelfDifferenceFloorFactor = 10.0;
// Pairwise orders of the self-differences wanted: four give two Aitken extrapolates, whose
// spread enters the uncertainty.
constexpr std::size_t kSelfDifferenceOrders = 4;

// The variables whose extrapolation from the reference errors was refused for want of pairwise
// orders (fewer than three trusted).
std::vector<std::size_t> short_of_orders(const std::vector<std::optional<OrderExtrapolation>>& extrapolations) {
  std::vector<std::size_t> wanted;
  for (std::size_t v = 0; v < extrapolations.size(); ++v) {
    const std::optional<OrderExtrapolation>& x = extrapolations[v];
    if (x && !x->computed && x->pairwise.size() < 3) wanted.push_back(v);
  }
  return wanted;
}

// Variable v's differences between successive levels, trusted then beyond, with the finer Δt of
// each; false when the newest one is within kSelfDifferenceFloorFactor of its round-off floor
// (it is left out).
bool self_differences(const StudyResult& result, const std::vector<LevelResult>& beyond, std::size_t v,
                      std::vector<double>& difference, std::vector<double>& dt) {
  difference.clear();
  dt.clear();
  auto add = [&](const LevelResult& level) {
    if (!level.self_difference[v]) return true;
    const LevelErrors at{level.dt, level.steps, *level.self_difference[v], level.norms[v].reference_l2};
    if (!(at.error > kSelfDifferenceFloorFactor * round_off_floor(at))) return false;
    difference.push_back(at.error);
    dt.push_back(level.dt);
    return true;
  };
  for (const LevelResult& level : result.levels) add(level);
  for (const LevelResult& level : beyond)
    if (!add(level)) return false;
  return true;
}

// Why no level beyond the reference's trust may start (budget, level limit, whole steps), or empty.
std::string cannot_go_beyond(const StudyPlan& plan, const std::vector<LevelResult>& beyond, int levels,
                             const LevelSearchRules& rules, double elapsed, long& steps) {
  if (levels >= rules.max_levels) return printf_string("%d levels were solved, the most a search keeps", levels);
  const double next = beyond.back().wall_seconds * plan.ratio;
  if (distribution().any(elapsed + next > rules.budget_seconds))  // agreed between ranks, as in cannot_refine
    return printf_string("the next level would take about %.3g s, past the budget of %.3g s", next,
                         rules.budget_seconds);
  StudyPlan next_plan = plan;
  next_plan.levels = levels + 1;
  try {
    steps = level_steps(next_plan).back();
  } catch (const InputError& e) {
    return "no finer level: " + e.reason();
  }
  return {};
}

}  // namespace

std::string refine_by_self_differences(Search& s, const StudyResult& result, const Solve& solve, double spent,
                                       const std::function<bool()>& stop,
                                       std::vector<std::optional<OrderExtrapolation>>& extrapolations) {
  const LevelSearchRules& rules = s.rules;
  const std::vector<std::size_t> wanted = short_of_orders(extrapolations);
  if (wanted.empty() || !s.left_out) return {};
  const std::string note = "beyond the reference's trust: its difference from the level before is used for the "
                           "self-difference orders, its error against the reference only for information";
  s.record.run.back().note = note;
  std::vector<LevelResult> beyond{*s.left_out};
  State previous = std::move(s.left_out_state);
  const auto begin = std::chrono::steady_clock::now();
  std::string ended;
  for (;;) {
    bool done = true;
    for (std::size_t v : wanted) {
      std::vector<double> difference, dt;
      const bool above_floor = self_differences(result, beyond, v, difference, dt);
      OrderExtrapolation x = extrapolate_self_differences(difference, s.plan.ratio);
      x.difference_dt.assign(dt.end() - static_cast<std::ptrdiff_t>(std::min(dt.size(), x.pairwise.size() + 1)),
                             dt.end());
      x.reference_trusted_to = result.levels.back().dt;
      if (!above_floor) ended = s.plan.variables[v].name + "'s newest self-difference is within 10 x of its round-off floor";
      else if (!x.computed && x.pairwise.size() >= 3)
        ended = s.plan.variables[v].name + "'s self-difference orders depart from the geometric pattern";
      done = done && x.computed && x.pairwise.size() >= kSelfDifferenceOrders;
      extrapolations[v] = std::move(x);
    }
    if (done) ended = "the self-difference orders were extrapolated";
    const double elapsed = spent + std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    long steps = 0;
    const int levels = static_cast<int>(result.levels.size() + beyond.size());
    if (ended.empty()) ended = cannot_go_beyond(s.plan, beyond, levels, rules, elapsed, steps);
    if (!ended.empty()) break;
    if (stop && stop()) throw StudyStopped(levels);
    StudyPlan plan = s.plan;
    plan.levels = levels + 1;
    State state;
    beyond.push_back(run_level(plan, levels, steps, *s.reference, solve, &previous, state));
    s.record.run.push_back({beyond.back().dt, steps, false, note});
    previous = std::move(state);
  }
  return printf_string("; refinement went on %zu level(s) beyond the reference's trust for the differences between "
                       "successive levels (",
                       beyond.size()) +
         ended + ")";
}

}  // namespace dlpverify::search_phase
