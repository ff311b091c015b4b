/// @file
/// The order extrapolated from pairwise orders that converge geometrically (docs/verification.md,
/// "Levels found by the study", "An order extrapolated from the pairwise orders").
///
/// With e = C Δt^p (1 + D Δt^m + …) the pairwise order between Δt_k and Δt_k / r is
/// p_k ≈ p + c Δt_k^m: the gaps g_k = p_{k+1} − p_k shrink by r^−m a level. Aitken's Δ² on the
/// last three pairwise orders gives the limit of such a sequence with no assumption on m,
///   p∞ = p_{k+1} − g_k² / (g_k − g_{k−1}).
/// It is made only when the sequence shows that signature: at least three pairwise orders (four
/// trusted levels), every gap of one sign, each gap ratio g_k / g_{k−1} in (0, 1) and the ratios
/// within a factor 2 of each other. A level search uses it when its straight fit could not settle.
///
/// The differences between successive levels, d_k = ‖y_{k−1} − y_k‖ ≈ C Δt_{k−1}^p (1 − r^−p)
/// (1 + D′ Δt_{k−1} + …), need no reference and have the same order and the same correction
/// term: their pairwise orders are extrapolated by the same rule.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/order.hpp"

namespace dlpverify {

/// An order extrapolated from pairwise orders, or why none was.
struct OrderExtrapolation {
  bool computed = false;          ///< the sequence converges geometrically and p∞ was made
  double value = 0.0;             ///< p∞, Aitken's Δ² on the last three pairwise orders
  /// |p∞ − p_last| (the last Aitken step) + |p∞ − p∞'| (p∞' Aitken's on the three before, when there
  /// are four pairwise orders): the whole correction counted as its own uncertainty
  double half_width = 0.0;
  std::vector<double> pairwise;    ///< the pairwise orders used, coarse to fine
  std::vector<double> gap_ratios;  ///< g_k / g_{k−1}, one per pair of successive gaps
  std::string refusal;             ///< why no order was extrapolated (empty when computed)
  /// "reference errors" (pairwise orders of the errors against the reference) or "self-differences"
  /// (pairwise orders of the differences between successive levels)
  std::string source = "reference errors";
  /// For self-differences: the finer Δt of each difference used, coarse to fine
  std::vector<double> difference_dt;
  /// For self-differences: the finest Δt the reference trusts (0 when not given)
  double reference_trusted_to = 0.0;
};

/// The extrapolation of the pairwise orders `pairwise` (coarse to fine; the last at most four are
/// used), or a refusal saying why the sequence does not converge geometrically.
OrderExtrapolation extrapolate_order(const std::vector<double>& pairwise);

/// The extrapolation of `analysis`'s pairwise orders between successive `ok` levels, over the run
/// of `ok` levels that ends at the finest one.
OrderExtrapolation extrapolate_order(const OrderAnalysis& analysis);

/// The extrapolation of the pairwise orders ln(d_{k−1} / d_k) / ln r of the differences between
/// successive levels `differences` (coarse to fine, all positive), with source "self-differences".
OrderExtrapolation extrapolate_self_differences(const std::vector<double>& differences, double ratio);

/// "order 3.972 ± 0.098 extrapolated (Aitken) from pairwise orders 4.258, 4.137, 4.070
/// (pre-asymptotic: gap ratios 0.60, 0.58)", or "no extrapolated order: REFUSAL".
std::string describe(const OrderExtrapolation& extrapolation);

/// {value, half_width, pairwise_orders, gap_ratios, method: "aitken", source} when computed, else
/// {refused, pairwise_orders, source}; for self-differences also difference_dt and reference_trusted_to.
nlohmann::json to_json(const OrderExtrapolation& extrapolation);

}  // namespace dlpverify
