// Observed order of accuracy (SPEC §6): pairwise orders, the least-squares order with its
// standard error and 95% interval, and the status of every level (ok / round-off / unstable).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace dlpverify {

enum class LevelStatus { ok, round_off, unstable };
std::string to_string(LevelStatus status);

// Least-squares slope of ln e against ln Δt (GSL gsl_fit_linear), Student-t 95% interval.
struct OrderFit {
  bool valid = false;         // at least two levels were fitted
  double value = 0.0;         // fitted order
  double stderr_ = 0.0;       // standard error of the slope (NaN with two levels: no residual left)
  double ci_low = 0.0, ci_high = 0.0;  // 95% interval (NaN with two levels)
  std::vector<int> levels;    // the levels the fit used
};
OrderFit fit_order(const std::vector<double>& dt, const std::vector<double>& error, const std::vector<int>& levels);

// Everything the harness concludes about one measured variable over the levels.
struct OrderAnalysis {
  std::vector<std::optional<double>> pairwise;  // p_k = ln(e_{k−1}/e_k) / ln r; none on level 0
  std::vector<LevelStatus> status;
  std::vector<std::string> rule;                // why each status was given
  std::vector<double> floor;                    // round-off floor of each level
  OrderFit fit;
  bool exact_to_round_off = false;              // every level sits at the floor
};

struct LevelErrors {
  double dt;
  long steps;
  double error;           // absolute L2 error
  double solution_size;   // √(Σ_p ‖y_p(t)‖²)
};

// The round-off floor of a level: C · ε · steps · ‖y‖ with C = kRoundOffPerStep. A step of an
// s-stage method rounds each component about 2s + 1 times at ~ε of its size, and the floor lets
// those roundings add up in the worst case (linear in steps). Measured on the exact cases (RK2,
// Heun, RK4 on similarity and gravity, R_out 10, 20–320 steps): errors of 0.2–0.5 ε·steps·‖y‖;
// and SPEC §6 records a 6th-order method flattening near 12 ε·steps·‖y‖. C = 10 keeps exact cases
// ≥ 19× under the floor and real truncation errors (RK4, drag, 320 steps) ≥ 7× above it.
inline constexpr double kRoundOffPerStep = 10.0;
double round_off_floor(const LevelErrors& level);

// Inputs whose effect is documented in the rules. A level within `near_floor_factor` of its floor
// whose pairwise order has fallen below `rate_drop_fraction` × the expected order has stopped
// converging because of round-off (SPEC §6), and is left out like a level at the floor.
struct OrderRules {
  double ratio = 2.0;                // refinement ratio r
  double expected_order = 0.0;       // 0: unknown (no rate-drop rule)
  double near_floor_factor = 100.0;
  double rate_drop_fraction = 0.75;
};

OrderAnalysis analyse_order(const std::vector<LevelErrors>& levels, const OrderRules& rules);

}  // namespace dlpverify
