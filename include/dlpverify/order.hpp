/// @file
/// Observed order of accuracy (docs/model.md §6): pairwise orders, the least-squares order with its
/// standard error and 95% interval, and the status of every level (ok / round-off / unstable).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dlpverify/error_constant.hpp"
#include "dlpverify/precision.hpp"

namespace dlpverify {

/// What a level's error says about convergence.
enum class LevelStatus {
  ok,         ///< in the asymptotic range: the order fit uses it
  round_off,  ///< at the round-off floor, stopped falling near it, or stopped falling for good after converging
  unstable,   ///< not finite, as large as the solution, or coarser than a level whose error grows under refinement
  pre_asymptotic,  ///< coarser than the asymptotic window: its pairwise order still moves towards the finer levels'
  /// under kMinimumReferenceMargin × the reference's estimated error (OrderRules::reference_error), or finer
  /// than such a level: its error measures the reference, not the integrator
  reference
};
/// "ok", "round-off", "unstable", "pre-asymptotic" or "reference", as reports print it.
std::string to_string(LevelStatus status);

/// Least-squares slope of ln e against ln Δt (GSL gsl_fit_linear), Student-t 95% interval.
/// The fitted order p of e ≈ C Δt^p over some levels.
struct OrderFit {
  bool valid = false;         ///< at least two levels were fitted
  double value = 0.0;         ///< fitted order
  double stderr_ = 0.0;       ///< standard error of the slope (NaN with two levels: no residual left)
  double ci_low = 0.0,        ///< low end of the 95% interval, value − t_{0.975, n−2} stderr_ (NaN with two levels)
      ci_high = 0.0;          ///< high end of the 95% interval, value + t_{0.975, n−2} stderr_ (NaN with two levels)
  std::vector<int> levels;    ///< the levels the fit used
};
/// The least-squares fit of ln error against ln dt over the indices in `levels`; invalid with fewer than two.
OrderFit fit_order(const std::vector<double>& dt, const std::vector<double>& error, const std::vector<int>& levels);

/// Everything the harness concludes about one measured variable over the levels.
struct OrderAnalysis {
  std::vector<std::optional<double>> pairwise;  ///< p_k = ln(e_{k−1}/e_k) / ln r; none on level 0
  std::vector<LevelStatus> status;              ///< the status of each level
  std::vector<std::string> rule;                ///< why each status was given
  std::vector<double> floor;                    ///< round-off floor of each level
  OrderFit fit;                                 ///< over the `ok` levels: the asymptotic window
  /// The pairwise orders between the window's finest four levels, finest last, the pre-asymptotic
  /// levels just coarser than the window counted (fewer when there are fewer levels): a verdict reads
  /// from them whether the order still moves, and how
  std::vector<double> finest_orders;
  /// How far rounding may move the window's finest pairwise order: kRoundingSpread × (F_b/e_b +
  /// F_{b−1}/e_{b−1}) / ln r over its two finest levels, F the floor and e the error (0 without a window)
  double rounding_spread = 0.0;
  /// e_b / floor_b of the window's finest level (0 without a window): how far above the modelled
  /// floor its error lies, for a verdict to tell a drop at the floor from an emerging lower order
  double finest_error_over_floor = 0.0;
  /// OrderRules::stall_reach the analysis used: errors within this × their floor may be rounding
  double stall_reach = 0.0;
  /// C of e ≈ C Δt^p over the fit's levels, p = error_constant_order(fit, the rules' expected
  /// order) (invalid when that order is unknown, or p < 1)
  ErrorConstant constant;
  double overall_slope = 0.0;                   ///< slope of ln e against ln Δt over all finite levels
  bool exact_to_round_off = false;              ///< every level at round-off, and errors do not fall
};

/// One level's error, as the order analysis takes it.
struct LevelErrors {
  double dt;              ///< the level's time step Δt_k
  long steps;             ///< its step count t_end / Δt_k
  double error;           ///< absolute L2 error
  double solution_size;   ///< √(Σ_p ‖y_p(t)‖²)
};

/// The round-off floor of a level: ½ ε √steps ‖y‖, the size of a random walk of one rounding of
/// ε/2 per component per step. An error at or below it is round-off for certain.
///
/// No floor set a priori separates every case, so it is kept low and the trend decides above it
/// (docs/model.md §6): measured on R_out 6–10 clouds, exact cases under gravity round off to ~110 ε‖y‖
/// after 320 steps (v − gΔt rounds the same way every step), while ARKODE's Verner 6th-order
/// table still converges at order 6.16 with an error of 12.5 ε‖y‖ after 160 steps.
/// `epsilon` is the arithmetic's machine epsilon: double's 2^−52, or Extended's 2^−104 for a study
/// in extended precision (dlpverify/precision.hpp).
double round_off_floor(const LevelErrors& level, double epsilon = kDoubleEpsilon);

/// Rounding noise as a multiple of the modelled floor: exact cases under gravity round off to
/// ~110 ε‖y‖ after 320 steps, 12 × ½ ε √320 ‖y‖ (docs/verification.md, "The asymptotic window").
inline constexpr double kRoundingSpread = 12.0;

/// A level within `near_floor_factor` of its floor whose error no longer falls at
/// `rate_drop_fraction` × the expected order has stopped converging because of round-off: the
/// pairwise order into it is too low (or, on the first level, the error does not fall to the
/// next). Such levels, and finer ones within the band, are left out of the fit.
struct OrderRules {
  double ratio = 2.0;                ///< refinement ratio r
  double expected_order = 0.0;       ///< 0: unknown (no rate-drop rule)
  double near_floor_factor = 1000.0;  ///< "near the floor": error ≤ this × round_off_floor
  double rate_drop_fraction = 0.75;   ///< a pairwise order below this × expected_order has dropped
  /// Errors that fall no faster than this over all levels do not converge: with every level at
  /// round-off, the method is exact. Errors that do fall are never called exact.
  double exact_max_slope = 0.5;
  /// An error that falls by less than r^stall_order to the next level has stopped falling; after
  /// levels that converged, within `stall_reach` × its floor, and with no finer level back on the
  /// converged trend, it and every finer level are round-off: the floor of this problem's rounding
  /// (a chaotic orbit's can lie 10⁴ × above the model), found from the errors themselves
  double stall_order = 0.5;
  double stall_reach = 1e5;  ///< how far above the modelled floor a stall may still be rounding
  /// The coarsest level of the window leaves it (pre-asymptotic) while the window keeps three or more
  /// levels and the pairwise order into the next level differs from the finer levels' fitted order
  /// by more than this and by more than the next pairwise order does
  double settle_width = 0.05;
  /// The reference's estimated error of this variable (0: a closed form, exact to round-off). A
  /// level whose error is under kMinimumReferenceMargin × it, and every finer level, measure the reference:
  /// they leave the fit, as levels at the round-off floor do.
  double reference_error = 0.0;
  /// The machine epsilon of the arithmetic the levels were computed in (round_off_floor).
  double epsilon = kDoubleEpsilon;
};

/// A reference is trusted when a level's error is at least this many times its own estimated
/// error: otherwise the level measures the reference, not the integrator (its error is more than
/// 1 % of what is measured).
inline constexpr double kMinimumReferenceMargin = 100.0;

/// Pairwise orders, the status of each level under `rules`, and the fit over the `ok` levels.
OrderAnalysis analyse_order(const std::vector<LevelErrors>& levels, const OrderRules& rules);

/// The order p the error constant of e ≈ C Δt^p is fitted at: the expected order P while the
/// fitted order names it (|p̂ − P| ≤ 1/2, or no fit), else the integer nearest the fitted order p̂.
/// C at P of errors that fall as Δt¹ is no constant (C_k = e_k/Δt_kᴾ grows as Δt shrinks) and
/// depends on the levels chosen; at the order the errors show it is the method's leading term.
/// When that integer is below 1 there is no constant (fit_error_constant refuses p ≤ 0).
double error_constant_order(const OrderFit& fit, double expected_order);

/// Why the window's finest pairwise orders do not settle on P as an order-P expansion's do, or ""
/// when they do (or too few are seen). With e = C Δtᴾ (1 + a Δt + …) the orders approach P; a
/// lower-order term c Δt^q (q < P), however small its c, grows r-fold against C Δtᴾ from level to
/// level and carries them away. Beyond rounding's reach (OrderAnalysis::rounding_spread) and
/// `least_change` (the smallest change of order that counts), they do not settle when the finest
/// order lies farther from P than the one before it, when each of the finest three lies farther
/// from P than the one before (|p₁ − P| < |p₂ − P| < |p₃ − P|, by more than those limits in all:
/// steps each too small to count), or when the orders turn back by a step more than √r times the
/// one before (s₁ = p₂ − p₁, s₂ = p₃ − p₂ of opposite signs, |s₂| > √r |s₁|).
std::string unsettled_orders(const OrderAnalysis& a, double expected, double ratio, double least_change);

/// Reference-free convergence (docs/model.md §6), from the differences between successive levels,
/// d_k = ‖y_{k−1} − y_k‖ (L2 over the cloud, k ≥ 1):
/// @code{.unparsed}
///   self-convergence order   p_k = ln(d_{k−1} / d_k) / ln r            (k ≥ 2, three levels)
///   Richardson error estimate of level k   e_k ≈ d_k / (r^p − 1)
///   Roache's grid convergence index        GCI_k = F_s (d_k / ‖y_k‖) / (r^p − 1), F_s = 1.25
/// @endcode
/// The estimates of the finest level use its own self-convergence order p.
struct SelfConvergence {
  std::vector<std::optional<double>> difference;  ///< d_k, none on level 0
  std::vector<std::optional<double>> order;       ///< p_k, none on levels 0 and 1
  std::optional<double> richardson_error;         ///< of the finest level, absolute L2
  std::optional<double> gci;                      ///< of the finest level, relative
};
inline constexpr double kGciSafetyFactor = 1.25;  ///< Roache's F_s for three or more levels
/// Self-convergence orders and the finest level's Richardson estimate and GCI from the differences
/// d_k (`difference`, none on level 0), the finest level's size ‖y‖ and the refinement ratio r.
SelfConvergence analyse_self_convergence(const std::vector<std::optional<double>>& difference, double finest_size,
                                         double ratio);

}  // namespace dlpverify
