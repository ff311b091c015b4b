#include "harness/ode_residual.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/evaluate_rhs.hpp"
#include "dlpverify/solution_features.hpp"
#include "harness/field_groups.hpp"

namespace dlpverify {

namespace {
// Weights of the 8th-order central first difference, D_h y = Σ_k c_k [y(τ + k h) − y(τ − k h)] / h.
constexpr std::array<double, 4> kCentral8{4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0};

// Step / time scale. Write u = h / T. If the nearest singularity of the solution in the complex τ
// plane is a distance T away (drag: s = s0 / (1 + K s0 τ) has its pole at 1/(K s) before τ), then
// y⁽⁹⁾ ≈ 8! y′ / T⁸ and the truncation error of D_h, (h⁸/630) y⁽⁹⁾, is 64 u⁸ relative to y′.
// Rounding each y(τ ± k h) at ε‖y‖ adds 2 Σ|c_k| ε ‖y‖ / h ≈ 2.08 ε T / h = 2.08 ε / u relative
// (taking ‖y‖/‖y′‖ ≈ T). The sum 64 u⁸ + 2.08 ε / u is smallest at u⁹ = 2.08 ε / 512, u ≈ 0.0099:
// h = 0.01 T gives a truncation of ~6e-15 and a round-off of ~5e-14.
constexpr double kStepPerTimeScale = 0.01;
// For τ > 0 the stencil is kept inside [τ/2, 3τ/2] — never reaching back to the launch, where a
// closed form may change branch (a particle launched at rest under gravity is at an apex at
// τ = 0) — as long as that costs at most 10× the optimal round-off (h ≥ T / 1000, ~5e-13
// relative). For smaller τ, or τ ≤ 0, the stencil is centred on τ and the closed form must
// continue smoothly through τ = 0.
constexpr double kSmallestStepPerTimeScale = 1e-3;


// ‖D − f‖ / max(‖f‖, ‖y‖ / T, DBL_MIN) over one group's fields of member p.
double group_residual(const State& difference, const State& rate, const State& y, Eigen::Index p, const Variable& g,
                      double scale) {
  double mismatch = 0.0, rate_size = 0.0, state_size = 0.0;
  for (int f = g.first_field; f < g.first_field + g.fields; ++f) {
    mismatch += (difference(p, f) - rate(p, f)) * (difference(p, f) - rate(p, f));
    rate_size += rate(p, f) * rate(p, f);
    state_size += y(p, f) * y(p, f);
  }
  const double denominator =
      std::max({std::sqrt(rate_size), std::sqrt(state_size) / scale, std::numeric_limits<double>::min()});
  return std::sqrt(mismatch) / denominator;
}

// The finite difference D_h y of every member at step h (members outside a bucket are computed too
// and ignored: a closed form is evaluated for the whole population at once).
State central_difference(const Problem& problem, const State& initial, double tau, double h) {
  State difference = State::Zero(initial.rows(), initial.cols());
  for (int k = static_cast<int>(kCentral8.size()); k >= 1; --k)  // smallest weights first
    difference += kCentral8[static_cast<std::size_t>(k - 1)] *
                  (closed_form(problem, initial, tau + k * h) - closed_form(problem, initial, tau - k * h));
  return difference / h;
}

// Members whose optimal steps lie within a factor kBucketWidth share the bucket's smallest one, so
// none is differenced at more than kBucketWidth times below its optimum (round-off ≤ 8 × 5e-14),
// while a population whose time scales span decades costs a few stencils, not one per member.
constexpr double kBucketWidth = 8.0;
int bucket_of(double step) { return static_cast<int>(std::floor(std::log(step) / std::log(kBucketWidth))); }

}  // namespace

double OdeResidual::max() const {
  double largest = 0.0;
  for (double r : groups) largest = std::max(largest, r);
  return largest;
}

OdeResidual ode_residual(const Problem& problem, const State& initial, double tau) {
  const State y = closed_form(problem, initial, tau);
  State rate;
  evaluate_rhs(problem, problem.initial_time() + tau, y, rate);
  const Eigen::Index members = y.rows();

  // Each member's scale T and optimal step; the members grouped by bucket_of(step).
  std::vector<double> scales(static_cast<std::size_t>(members));
  std::map<int, std::vector<Eigen::Index>> buckets;
  std::map<int, double> bucket_step;  // the smallest member step of each bucket
  std::vector<Eigen::Index> unlimited;  // members nothing limits: differenced at the largest step
  for (Eigen::Index p = 0; p < members; ++p) {
    std::vector<double> member_fields(static_cast<std::size_t>(y.cols()));
    for (Eigen::Index f = 0; f < y.cols(); ++f) member_fields[static_cast<std::size_t>(f)] = y(p, f);
    const double scale = time_scale(problem, p, member_fields.data(), tau);
    scales[static_cast<std::size_t>(p)] = scale;
    double member_step = kStepPerTimeScale * scale;
    if (tau > 0.0) member_step = std::min(member_step, std::max(tau / 8.0, kSmallestStepPerTimeScale * scale));
    if (!std::isfinite(member_step) || !(member_step > 0.0)) {
      unlimited.push_back(p);
      continue;
    }
    const int bucket = bucket_of(member_step);
    buckets[bucket].push_back(p);
    auto [it, first] = bucket_step.emplace(bucket, member_step);
    if (!first) it->second = std::min(it->second, member_step);
  }
  OdeResidual r;
  const std::vector<Variable> groups = field_groups(problem);
  r.groups.assign(groups.size(), 0.0);
  if (buckets.empty()) return r;
  std::vector<Eigen::Index>& largest = buckets.rbegin()->second;
  largest.insert(largest.end(), unlimited.begin(), unlimited.end());
  r.time_scale = *std::min_element(scales.begin(), scales.end());
  r.step = std::numeric_limits<double>::infinity();

  const std::vector<double> kinks = kink_times(problem, initial);
  for (const auto& [bucket, bucket_members] : buckets) {
    double h = bucket_step.at(bucket);
    // Make τ + h exact, so the stencil's offsets are (very nearly) the multiples of h they claim to be.
    const double representable = (tau + h) - tau;
    if (representable > 0.0) h = representable;
    r.step = std::min(r.step, h);
    const State difference = central_difference(problem, initial, tau, h);
    for (Eigen::Index p : bucket_members) {
      const double kink = kinks[static_cast<std::size_t>(p)];
      if (std::isfinite(kink) && std::abs(kink - tau) <= 4.5 * h) {
        ++r.skipped;
        continue;
      }
      for (std::size_t g = 0; g < groups.size(); ++g) {
        const double residual = group_residual(difference, rate, y, p, groups[g], scales[static_cast<std::size_t>(p)]);
        if (std::isfinite(residual))
          r.groups[g] = std::max(r.groups[g], residual);
        else
          ++r.non_finite;
      }
    }
  }
  return r;
}

}  // namespace dlpverify
