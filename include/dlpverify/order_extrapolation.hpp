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
};

/// The extrapolation of the pairwise orders `pairwise` (coarse to fine; the last at most four are
/// used), or a refusal saying why the sequence does not converge geometrically.
OrderExtrapolation extrapolate_order(const std::vector<double>& pairwise);

/// The extrapolation of `analysis`'s pairwise orders between successive `ok` levels, over the run
/// of `ok` levels that ends at the finest one.
OrderExtrapolation extrapolate_order(const OrderAnalysis& analysis);

/// "order 3.972 ± 0.098 extrapolated (Aitken) from pairwise orders 4.258, 4.137, 4.070
/// (pre-asymptotic: gap ratios 0.60, 0.58)", or "no extrapolated order: REFUSAL".
std::string describe(const OrderExtrapolation& extrapolation);

/// {value, half_width, pairwise_orders, gap_ratios, method: "aitken"} when computed, else {refused}.
nlohmann::json to_json(const OrderExtrapolation& extrapolation);

}  // namespace dlpverify
