#include "dlpverify/order_extrapolation.hpp"

#include <algorithm>
#include <cmath>

#include "io/format.hpp"

namespace dlpverify {

namespace {

// A gap below this is the pairwise order's own rounding (ln of a ratio of errors, each good to a
// few ulps, over ln r): the orders stand still and there is no trend to extrapolate.
constexpr double kStillGap = 1e-6;
// Successive gap ratios may differ by at most this factor: a geometric sequence has one ratio,
// r^−m; the next term of the error series bends it a little, noise or a second regime bends it more.
constexpr double kRatioSpread = 2.0;
// At most this many trailing pairwise orders are used: enough for two Aitken extrapolates.
constexpr std::size_t kMostUsed = 4;

// Aitken's Δ² on p0, p1, p2: the limit of a sequence whose gaps shrink geometrically.
double aitken(double p0, double p1, double p2) {
  const double g0 = p1 - p0, g1 = p2 - p1;
  return p2 - g1 * g1 / (g1 - g0);
}

std::string list(const std::vector<double>& values, const char* format) {
  std::string text;
  for (double value : values) text += (text.empty() ? "" : ", ") + printf_string(format, value);
  return text;
}

}  // namespace

OrderExtrapolation extrapolate_order(const std::vector<double>& pairwise) {
  OrderExtrapolation x;
  x.pairwise.assign(pairwise.end() - static_cast<std::ptrdiff_t>(std::min(pairwise.size(), kMostUsed)), pairwise.end());
  const std::vector<double>& p = x.pairwise;
  if (p.size() < 3) {
    x.refusal = printf_string("needs 3 pairwise orders (4 trusted levels), has %zu", p.size());
    return x;
  }
  std::vector<double> gaps;
  for (std::size_t k = 1; k < p.size(); ++k) gaps.push_back(p[k] - p[k - 1]);
  for (double gap : gaps)
    if (!(std::abs(gap) > kStillGap)) {
      x.refusal = "the pairwise orders do not move (gaps " + list(gaps, "%.2g") + "): nothing to extrapolate";
      return x;
    }
  for (std::size_t k = 1; k < gaps.size(); ++k) x.gap_ratios.push_back(gaps[k] / gaps[k - 1]);
  for (double q : x.gap_ratios)
    if (!(q > 0.0 && q < 1.0)) {
      x.refusal = "the pairwise orders " + list(p, "%.3f") + " do not converge geometrically (gap ratios " +
                  list(x.gap_ratios, "%.2f") + ", each must be in (0, 1))";
      return x;
    }
  const auto [low, high] = std::minmax_element(x.gap_ratios.begin(), x.gap_ratios.end());
  if (*high > kRatioSpread * *low) {
    x.refusal = "the gap ratios " + list(x.gap_ratios, "%.2f") + " of the pairwise orders differ by more than 2 x";
    return x;
  }
  const std::size_t n = p.size();
  x.value = aitken(p[n - 3], p[n - 2], p[n - 1]);
  // Aitken is exact for a purely geometric gap sequence; what it misses is the next term of the
  // error series, smaller than the correction it made. Counting the whole correction, and the
  // spread to the extrapolate one level coarser, as the uncertainty bounds that with room.
  x.half_width = std::abs(x.value - p[n - 1]);
  if (n >= 4) x.half_width += std::abs(x.value - aitken(p[n - 4], p[n - 3], p[n - 2]));
  x.computed = true;
  return x;
}

OrderExtrapolation extrapolate_order(const OrderAnalysis& analysis) {
  // Pre-asymptotic levels are trusted here: their pairwise orders are the sequence that converges.
  const auto trusted = [&](std::size_t k) {
    return analysis.status[k] == LevelStatus::ok || analysis.status[k] == LevelStatus::pre_asymptotic;
  };
  std::vector<double> pairwise;
  int finest = static_cast<int>(analysis.status.size()) - 1;
  while (finest >= 0 && !trusted(static_cast<std::size_t>(finest))) --finest;
  for (int k = finest; k >= 1; --k) {
    const auto level = static_cast<std::size_t>(k);
    if (!trusted(level - 1) || !analysis.pairwise[level]) break;
    pairwise.insert(pairwise.begin(), *analysis.pairwise[level]);
  }
  return extrapolate_order(pairwise);
}

OrderExtrapolation extrapolate_self_differences(const std::vector<double>& differences, double ratio) {
  std::vector<double> pairwise;
  for (std::size_t k = 1; k < differences.size(); ++k)
    pairwise.push_back(std::log(differences[k - 1] / differences[k]) / std::log(ratio));
  OrderExtrapolation x = extrapolate_order(pairwise);
  x.source = "self-differences";
  return x;
}

std::string describe(const OrderExtrapolation& x) {
  const bool self = x.source == "self-differences";
  const std::string trust = self && x.reference_trusted_to > 0.0
                                ? printf_string("the reference trusts levels to %.4g s; ", x.reference_trusted_to)
                                : std::string();
  const std::string from = self ? "the differences between successive levels (no reference needed) " : "pairwise orders ";
  if (!x.computed) return trust + "no extrapolated order" + (self ? " from the differences between successive levels" : "") +
                          ": " + x.refusal;
  return trust + printf_string("order %.3f ± %.3f extrapolated (Aitken) from ", x.value, x.half_width) + from +
         list(x.pairwise, "%.3f") + " (pre-asymptotic: gap ratios " + list(x.gap_ratios, "%.2f") + ")";
}

nlohmann::json to_json(const OrderExtrapolation& x) {
  nlohmann::json json = x.computed ? nlohmann::json{{"value", x.value},
                                                    {"half_width", x.half_width},
                                                    {"pairwise_orders", x.pairwise},
                                                    {"gap_ratios", x.gap_ratios},
                                                    {"method", "aitken"}}
                                   : nlohmann::json{{"refused", x.refusal}, {"pairwise_orders", x.pairwise}};
  json["source"] = x.source;
  if (x.source == "self-differences") {
    json["difference_dt"] = x.difference_dt;
    json["reference_trusted_to"] = x.reference_trusted_to;
  }
  return json;
}

}  // namespace dlpverify
