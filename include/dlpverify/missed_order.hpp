/// @file
/// Why a variable missed its order, where the study shows a reason (docs/verification.md, "Why an
/// order was missed"): the coarse steps are beyond the fastest time scale, the finest levels
/// are at the round-off floor, the reference is not accurate enough, the solution has a kink
/// inside the interval, or an inner iteration did not converge.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// A reason a variable's order can be missed.
enum class MissReason {
  stability,           ///< levels unstable or pre-asymptotic, with Δt·ρ(J) of each
  round_off,           ///< levels at the round-off floor
  reference_accuracy,  ///< the finest level is within 100× of the reference's estimated error
  kink,                ///< members' solutions are only once differentiable inside (t0, t0 + t_end]
  inner_iteration,     ///< an implicit scheme's inner iteration did not converge on some level
};
/// "stability", "round-off", "reference-accuracy", "kink" or "inner-iteration".
std::string to_string(MissReason reason);

/// One reason, with the numbers that show it.
struct MissExplanation {
  MissReason reason;  ///< which
  std::string text;   ///< the evidence in a sentence
};

/// The largest |λ| of the Jacobian ∂f/∂y at (t, state). Members do not interact (the
/// right-hand side is evaluated by blocks), so J is block-diagonal with one F × F block per
/// member, formed by central differences: column j from f(y ± h_j e_j), h_j = ε^(1/3) ×
/// max(|y_j|, the field's size) (field_scales). Every member's block is bounded by its largest
/// absolute row sum (2F evaluations of the whole population), and the blocks whose bound exceeds
/// the largest |λ| found so far have their eigenvalues computed (Eigen's EigenSolver), so a real
/// ± pair and a complex pair count by their modulus. NaN when the right-hand side is not finite
/// at the state.
double spectral_radius(const Problem& problem, double t, const State& state);

/// What the problem tells about a missed order, computed once per study.
struct MissContext {
  double spectral_radius = 0.0;  ///< ρ(J) at the initial state and t0 [1/time unit]; 0: not estimated
  int kinks_inside = 0;          ///< members with a kink in (0, t_end] after t0
  double first_kink = 0.0;       ///< the earliest such kink time after t0
  double last_kink = 0.0;        ///< the latest
  Eigen::Index members = 0;      ///< the members the kinks were looked for in
  /// Per variable, a level search's extrapolated order (or why none was made), order_extrapolation.hpp;
  /// empty when none was tried
  std::vector<std::string> extrapolation;
};
/// ρ(J) at (t0, initial state) and the kink times inside the study's duration `t_end`.
MissContext miss_context(const Problem& problem, double t_end);

/// For each variable of `study` (in order): no reasons when its finding in `verdict` passed,
/// else every reason the study and `context` show; a missed order with no visible reason has an
/// empty list.
std::vector<std::vector<MissExplanation>> explain_missed_orders(const StudyResult& study, const CheckVerdict& verdict,
                                                                const MissContext& context);

/// The console lines: "why: VARIABLE: REASON — TEXT" for each reason; empty when none was seen.
std::string format_missed_orders(const StudyResult& study, const std::vector<std::vector<MissExplanation>>& reasons);
/// {"spectral_radius": ρ or null, "dt_spectral_radius": [Δt_k ρ per level],
///  "reasons": {VARIABLE: [{"reason", "text"}…] for each missed variable}}.
nlohmann::json to_json(const StudyResult& study, const MissContext& context,
                       const std::vector<std::vector<MissExplanation>>& reasons);

}  // namespace dlpverify
