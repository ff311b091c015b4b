#include "dlpverify/order.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <limits>
#include <string>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>

#include "io/format.hpp"
#include "io/gsl_errors.hpp"

namespace dlpverify {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::string to_string(LevelStatus status) {
  switch (status) {
    case LevelStatus::ok: return "ok";
    case LevelStatus::round_off: return "round-off";
    case LevelStatus::unstable: return "unstable";
    case LevelStatus::pre_asymptotic: return "pre-asymptotic";
    case LevelStatus::reference: return "reference";
  }
  return "?";
}

OrderFit fit_order(const std::vector<double>& dt, const std::vector<double>& error, const std::vector<int>& levels) {
  OrderFit fit;
  fit.levels = levels;
  const std::size_t n = levels.size();
  if (n < 2) return fit;
  std::vector<double> log_dt(n), log_error(n);
  for (std::size_t i = 0; i < n; ++i) {
    log_dt[i] = std::log(dt[levels[i]]);
    log_error[i] = std::log(error[levels[i]]);
  }
#ifdef DLPVERIFY_PLANT_BUGS
  // Planted bug (test-only build, tests/planted): an off-by-one loop bound writes one past log_dt.
  for (std::size_t i = 0; i <= n; ++i) log_dt.data()[i] = std::log(dt[levels[std::min(i, n - 1)]]);
#endif
  use_gsl_return_codes();  // a degenerate fit yields NaN, never abort()
  double intercept, slope, cov00, cov01, cov11, sum_squares;
  gsl_fit_linear(log_dt.data(), 1, log_error.data(), 1, n, &intercept, &slope, &cov00, &cov01, &cov11, &sum_squares);
  fit.valid = true;
  fit.value = slope;
  if (n > 2) {
    // gsl_fit_linear scales the covariance by the residual variance sum_squares / (n − 2).
    fit.stderr_ = std::sqrt(cov11);
    const double t = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(n - 2));
    fit.ci_low = slope - t * fit.stderr_;
    fit.ci_high = slope + t * fit.stderr_;
  } else {
    fit.stderr_ = fit.ci_low = fit.ci_high = kNaN;
  }
  return fit;
}

double round_off_floor(const LevelErrors& level, double epsilon) {
  const double size = level.solution_size > 0.0 ? level.solution_size : std::numeric_limits<double>::min();
  return 0.5 * epsilon * std::sqrt(static_cast<double>(std::max(level.steps, 1L))) * size;
}

namespace {

// The observed order between two levels i < j: ln(e_i / e_j) / ln(Δt_i / Δt_j).
double order_between(const std::vector<LevelErrors>& levels, std::size_t i, std::size_t j) {
  return std::log(levels[i].error / levels[j].error) / std::log(levels[i].dt / levels[j].dt);
}

// Round-off by the model: at or under the floor ½ ε √steps ‖y‖, or near it and no longer falling
// at the expected rate (order.hpp, OrderRules).
void mark_model_floor(const std::vector<LevelErrors>& levels, const OrderRules& rules, OrderAnalysis& a) {
  const std::size_t count = levels.size();
  const bool rate_rule = rules.expected_order > 0.0;
  const double slow = rules.rate_drop_fraction * rules.expected_order;  // a rate below this has dropped
  auto near_floor = [&](std::size_t k) { return levels[k].error <= rules.near_floor_factor * a.floor[k]; };
  std::optional<std::size_t> first_round_off;
  for (std::size_t k = 0; k < count; ++k) {
    const double e = levels[k].error;
    if (!std::isfinite(e)) {
      a.status[k] = LevelStatus::unstable;
      a.rule[k] = "error is not finite";
    } else if (levels[k].solution_size > 0.0 && e >= levels[k].solution_size) {
      a.status[k] = LevelStatus::unstable;
      a.rule[k] = printf_string("error %.3e is as large as the solution itself (%.3e)", e, levels[k].solution_size);
    } else if (e <= a.floor[k]) {
      a.status[k] = LevelStatus::round_off;
      a.rule[k] = printf_string("error %.3e <= floor eps*sqrt(steps)*|y|/2 = %.3e", e, a.floor[k]);
    } else if (near_floor(k) && first_round_off) {
      a.status[k] = LevelStatus::round_off;
      a.rule[k] = printf_string("error %.3e within %.0fx of its floor, finer than level %.0f at round-off", e,
                         rules.near_floor_factor, static_cast<double>(*first_round_off));
    } else if (rate_rule && near_floor(k) && a.pairwise[k] && *a.pairwise[k] < slow) {
      a.status[k] = LevelStatus::round_off;
      a.rule[k] = printf_string("error %.3e within %.0fx of its floor and falling at order %.2f", e, rules.near_floor_factor,
                         *a.pairwise[k]) +
                  printf_string(" < %.2f", slow);
    } else if (rate_rule && near_floor(k) && k == 0 && count > 1 && a.pairwise[1] && *a.pairwise[1] < slow) {
      a.status[k] = LevelStatus::round_off;
      a.rule[k] = printf_string("error %.3e within %.0fx of its floor and not falling to level 1 (order %.2f)", e,
                         rules.near_floor_factor, *a.pairwise[1]);
    }
    if (a.status[k] == LevelStatus::round_off && !first_round_off) first_round_off = k;
  }
}

// The reference's floor: from the first level whose error is under kMinimumReferenceMargin × the
// reference's estimated error, the levels measure the reference (OrderRules::reference_error).
void mark_reference_floor(const std::vector<LevelErrors>& levels, const OrderRules& rules, OrderAnalysis& a) {
  if (!(rules.reference_error > 0.0)) return;
  const double trusted = kMinimumReferenceMargin * rules.reference_error;
  std::optional<std::size_t> first;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    if (!first && std::isfinite(levels[k].error) && levels[k].error < trusted) first = k;
    if (!first || a.status[k] != LevelStatus::ok) continue;
    a.status[k] = LevelStatus::reference;
    a.rule[k] = k == *first ? printf_string("error %.3e under %.0fx the reference's estimated error %.3e", levels[k].error,
                                            kMinimumReferenceMargin, rules.reference_error)
                            : printf_string("finer than level %zu, which measures the reference", *first);
  }
}

// Round-off by the errors themselves: after levels that converged at order q, the first level k
// whose error falls by less than r^stall_order, within stall_reach × its floor, with no finer level
// back on the trend e_{k−1} r^{−q (j−k)}, has reached this problem's rounding floor; it and every
// finer level are round-off, and so is level k−1 when its own order had already dropped into it.
void mark_stalled_floor(const std::vector<LevelErrors>& levels, const OrderRules& rules, OrderAnalysis& a) {
  const std::size_t count = levels.size();
  const double converged_at = rules.expected_order > 0.0 ? rules.rate_drop_fraction * rules.expected_order : 1.0;
  double q = 0.0;  // the fastest convergence seen so far
  for (std::size_t k = 1; k < count; ++k) {
    if (a.status[k] != LevelStatus::ok || a.status[k - 1] != LevelStatus::ok || !a.pairwise[k]) {
      q = 0.0;
      continue;
    }
    const double p = *a.pairwise[k];
    if (p >= rules.stall_order || q < converged_at || levels[k].error > rules.stall_reach * a.floor[k]) {
      q = std::max(q, p);
      continue;
    }
    const double trend_order = rules.expected_order > 0.0 ? rules.expected_order : q;
    bool back_on_trend = false;
    for (std::size_t j = k; j < count; ++j)
      back_on_trend = back_on_trend || (std::isfinite(levels[j].error) &&
                                        levels[j].error <= levels[k - 1].error * std::pow(rules.ratio, -trend_order * double(j - k)));
    if (back_on_trend) continue;
    const std::string why = printf_string("error stops falling at level %zu (order %.2f after %.2f) %.0fx above its modelled "
                                          "floor, and no finer level returns to order %.2f: the floor of rounding here",
                                          k, p, q, levels[k].error / a.floor[k], trend_order);
    for (std::size_t j = k; j < count; ++j) {
      if (a.status[j] != LevelStatus::ok) continue;
      a.status[j] = LevelStatus::round_off;
      a.rule[j] = why;
    }
    if (k >= 3 && a.pairwise[k - 1] && a.pairwise[k - 2] && a.status[k - 2] == LevelStatus::ok &&
        *a.pairwise[k - 1] < *a.pairwise[k - 2] - 2.0 * rules.settle_width) {
      a.status[k - 1] = LevelStatus::round_off;
      a.rule[k - 1] = printf_string("falls at order %.2f (%.2f a level before) into the floor of level %zu",
                                    *a.pairwise[k - 1], *a.pairwise[k - 2], k);
    }
    return;
  }
}

// Instability or pre-asymptotic behaviour: the error grows under refinement away from the floor.
// Every level coarser than the growth is flagged, so the fit starts where refinement reduces the
// error; a growth at the floor was found above and flags nothing.
void mark_growth(const std::vector<LevelErrors>& levels, OrderAnalysis& a) {
  for (std::size_t k = 1; k < levels.size(); ++k) {
    if (a.status[k] != LevelStatus::ok || a.status[k - 1] == LevelStatus::round_off) continue;
    if (std::isfinite(levels[k - 1].error) && levels[k].error > levels[k - 1].error) {
      for (std::size_t j = 0; j < k; ++j) {
        if (a.status[j] != LevelStatus::ok) continue;
        a.status[j] = LevelStatus::unstable;
        a.rule[j] = printf_string("error grows under refinement from level %zu to level %zu (pre-asymptotic or unstable)",
                                  k - 1, k);
      }
    }
  }
}

// The asymptotic window: the `ok` levels, less the coarse ones whose order still moves towards
// the finer levels' (OrderRules::settle_width). Returns the window, coarsest first.
std::vector<int> prune_pre_asymptotic(const std::vector<LevelErrors>& levels, const OrderRules& rules, OrderAnalysis& a) {
  std::vector<double> dt, error;
  std::vector<int> window;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    dt.push_back(levels[k].dt);
    error.push_back(levels[k].error);
    if (a.status[k] == LevelStatus::ok) window.push_back(static_cast<int>(k));
  }
  while (window.size() > 3) {
    const auto coarse = static_cast<std::size_t>(window[0]), next = static_cast<std::size_t>(window[1]);
    const double finer = fit_order(dt, error, std::vector<int>(window.begin() + 1, window.end())).value;
    const double order = order_between(levels, coarse, next);
    const double next_order = order_between(levels, next, static_cast<std::size_t>(window[2]));
    if (!(std::abs(order - finer) > rules.settle_width && std::abs(next_order - finer) < std::abs(order - finer))) break;
    a.status[coarse] = LevelStatus::pre_asymptotic;
    a.rule[coarse] = printf_string("order %.2f to level %zu, %.2f from the finer levels' %.2f (next %.2f)",
                                   order, next, std::abs(order - finer), finer, next_order);
    window.erase(window.begin());
  }
  return window;
}

}  // namespace

double error_constant_order(const OrderFit& fit, double expected_order) {
  if (!fit.valid || std::abs(fit.value - expected_order) <= 0.5) return expected_order;
  return std::round(fit.value);
}

OrderAnalysis analyse_order(const std::vector<LevelErrors>& levels, const OrderRules& rules) {
  const std::size_t count = levels.size();
  OrderAnalysis a;
  a.pairwise.assign(count, std::nullopt);
  a.status.assign(count, LevelStatus::ok);
  a.rule.assign(count, "");
  a.floor.resize(count);
  const double log_ratio = std::log(rules.ratio);
  for (std::size_t k = 0; k < count; ++k) {
    a.floor[k] = round_off_floor(levels[k], rules.epsilon);
    if (k > 0 && levels[k].error > 0.0 && levels[k - 1].error > 0.0 && std::isfinite(levels[k].error) &&
        std::isfinite(levels[k - 1].error))
      a.pairwise[k] = std::log(levels[k - 1].error / levels[k].error) / log_ratio;
  }
  mark_model_floor(levels, rules, a);
  mark_reference_floor(levels, rules, a);
  mark_stalled_floor(levels, rules, a);
  mark_growth(levels, a);
  const std::vector<int> window = prune_pre_asymptotic(levels, rules, a);
  a.stall_reach = rules.stall_reach;

  std::vector<double> dt(count), error(count);
  std::vector<int> finite;
  bool all_round_off = count > 0;
  for (std::size_t k = 0; k < count; ++k) {
    dt[k] = levels[k].dt;
    error[k] = levels[k].error;
    if (std::isfinite(error[k]) && error[k] > 0.0) finite.push_back(static_cast<int>(k));
    if (a.status[k] == LevelStatus::ok) a.rule[k] = "in the asymptotic range";
    all_round_off = all_round_off && a.status[k] == LevelStatus::round_off;
  }
  const std::size_t n = window.size();
  std::vector<std::size_t> finest;  // the window's finest four levels, pre-asymptotic ones next to it included
  for (std::size_t k = n == 0 ? 0 : static_cast<std::size_t>(window.back()) + 1;
       k-- > 0 && finest.size() < 4 && (a.status[k] == LevelStatus::ok || a.status[k] == LevelStatus::pre_asymptotic);)
    finest.insert(finest.begin(), k);
  for (std::size_t i = 0; i + 1 < finest.size(); ++i) a.finest_orders.push_back(order_between(levels, finest[i], finest[i + 1]));
  if (n >= 2) {
    const auto b = static_cast<std::size_t>(window[n - 1]), before = static_cast<std::size_t>(window[n - 2]);
    a.rounding_spread = kRoundingSpread * (a.floor[b] / levels[b].error + a.floor[before] / levels[before].error) /
                        std::log(levels[before].dt / levels[b].dt);
    a.finest_error_over_floor = levels[b].error / a.floor[b];
  }
  const OrderFit overall = fit_order(dt, error, finite);
  // Errors exactly zero at every level (or all but one) do not fall either.
  a.overall_slope = overall.valid ? overall.value : 0.0;
  a.exact_to_round_off = all_round_off && a.overall_slope <= rules.exact_max_slope;
  a.fit = fit_order(dt, error, window);
  a.constant = fit_error_constant(dt, error, window, rules.expected_order > 0.0 ? error_constant_order(a.fit, rules.expected_order) : 0.0);
  return a;
}

SelfConvergence analyse_self_convergence(const std::vector<std::optional<double>>& difference, double finest_size,
                                         double ratio) {
  SelfConvergence s;
  s.difference = difference;
  s.order.assign(difference.size(), std::nullopt);
  const double log_ratio = std::log(ratio);
  for (std::size_t k = 2; k < difference.size(); ++k)
    if (difference[k] && difference[k - 1] && *difference[k] > 0.0 && *difference[k - 1] > 0.0)
      s.order[k] = std::log(*difference[k - 1] / *difference[k]) / log_ratio;
  if (difference.empty() || !s.order.back() || !difference.back()) return s;
  const double p = *s.order.back();
  const double denominator = std::pow(ratio, p) - 1.0;
  if (!(p > 0.0) || !(denominator > 0.0)) return s;  // not converging: no estimate
  s.richardson_error = *difference.back() / denominator;
  if (finest_size > 0.0) s.gci = kGciSafetyFactor * (*difference.back() / finest_size) / denominator;
  return s;
}

std::string unsettled_orders(const OrderAnalysis& a, double expected, double ratio, double least_change) {
  const std::size_t n = a.finest_orders.size();
  if (n < 2) return "";
  const double p2 = a.finest_orders[n - 2], p3 = a.finest_orders[n - 1];
  const double noise = std::max(a.rounding_spread, least_change);
  if (std::abs(p3 - expected) - std::abs(p2 - expected) > noise)
    return printf_string("its finest pairwise order moves away from %.3f (%.3f -> %.3f), where an order-P method's "
                         "approach it", expected, p2, p3);
  if (n < 3) return "";
  const double p1 = a.finest_orders[n - 3], s1 = p2 - p1, s2 = p3 - p2;
  const double d1 = std::abs(p1 - expected), d2 = std::abs(p2 - expected), d3 = std::abs(p3 - expected);
  if (d2 > d1 && d3 > d2 && d3 - d1 > noise)
    return printf_string("its finest pairwise orders keep moving away from %.3f (%.3f -> %.3f -> %.3f), where an "
                         "order-P method's approach it", expected, p1, p2, p3);
  if (s1 * s2 >= 0.0 || std::abs(s2) <= std::abs(s1) * std::sqrt(ratio) || std::abs(s2) <= noise) return "";
  return printf_string("its pairwise orders turn back by a step %.2f times the one before (%.3f -> %.3f -> %.3f), "
                       "where an order-P method's shrink towards P",
                       std::abs(s2 / s1), p1, p2, p3);
}

}  // namespace dlpverify
