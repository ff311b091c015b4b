#include "dlpverify/manufactured.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "dlpverify/errors.hpp"

namespace dlpverify {

namespace {

constexpr double kGoldenFraction = 0.6180339887498949;  // (√5 − 1)/2
constexpr double kSilverFraction = 0.4142135623730951;  // √2 − 1

double fraction(double x) { return x - std::floor(x); }

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

ManufacturedProblem::ManufacturedProblem(std::unique_ptr<const Problem> problem, double duration)
    : ManufacturedProblem(*problem, duration) {
  owned_ = std::move(problem);
}

ManufacturedProblem::ManufacturedProblem(const Problem& problem, double duration)
    : problem_(problem), duration_(duration), initial_(problem.initial_state()) {
  if (!(duration > 0.0) || !std::isfinite(duration))
    throw InputError("duration", number(duration), "a manufactured solution needs a positive, finite duration");
  if (!initial_.allFinite()) throw InputError("initial state", problem.name(), "has a value that is not finite");
  scale_ = field_scales(problem, initial_);
  inert_ = dlpverify::inert_fields(problem);
  provide<ClosedForm>(*this);
  provide<CaseReport>(*this);
  provide<InertFields>(*this);
  provide<StaggeredBlocks>(*this);
  if (problem.capability<LinearDecay>()) provide<LinearDecay>(*this);
  provide<TimeScale>(*this);
  provide<TimeUnit>(*this);
  provide<MemberNoun>(*this);
  if (problem.capability<MemberCoordinate>()) provide<MemberCoordinate>(*this);
  if (problem.capability<SweepContraction>()) provide<SweepContraction>(*this);
}

// ω_p = (2π / duration)(1 + ½ frac(p φ)): between one and one and a half turns over the study.
double ManufacturedProblem::omega(Eigen::Index p) const {
  return 2.0 * std::numbers::pi / duration_ * (1.0 + 0.5 * fraction(static_cast<double>(p) * kGoldenFraction));
}

void ManufacturedProblem::trajectory(Eigen::Index p, int f, double tau, double& value, double& rate) const {
  const double y0 = initial_(p, f);
  if (inert_[static_cast<std::size_t>(f)]) {
    value = y0;
    rate = 0.0;
    return;
  }
  const double w = omega(p);
  const double a = kManufacturedAmplitude;
  if (y0 == 0.0) {  // A s_f (1 − cos ωτ): starts at 0 with zero slope, never changes sign
    const double s = scale_[static_cast<std::size_t>(f)];
    value = a * s * (1.0 - std::cos(w * tau));
    rate = a * s * w * std::sin(w * tau);
    return;
  }
  // y0 exp(A [sin(ωτ + θ) − sin θ]), and its derivative ŷ A ω cos(ωτ + θ).
  const double theta = 2.0 * std::numbers::pi * fraction(static_cast<double>(p) * kGoldenFraction + f * kSilverFraction);
  value = y0 * std::exp(a * (std::sin(w * tau + theta) - std::sin(theta)));
  rate = value * a * w * std::cos(w * tau + theta);
}

void ManufacturedProblem::rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const {
  const int fields = field_count();
  const double tau = t - initial_time();
  // ŷ(t) and ŷ′(t) of the block, then f(t, ŷ): one more call of the problem's rhs per block.
  std::vector<double> at(static_cast<std::size_t>(2 * fields * count));
  double* trajectory_values = at.data();
  double* trajectory_rates = at.data() + fields * count;
  std::vector<const double*> y_hat(static_cast<std::size_t>(fields));
  std::vector<double*> f_hat(static_cast<std::size_t>(fields));
  std::vector<double> f_storage(static_cast<std::size_t>(fields * count));
  for (int f = 0; f < fields; ++f) {
    for (int i = 0; i < count; ++i)
      trajectory(first + i, f, tau, trajectory_values[f * count + i], trajectory_rates[f * count + i]);
    y_hat[static_cast<std::size_t>(f)] = trajectory_values + f * count;
    f_hat[static_cast<std::size_t>(f)] = f_storage.data() + f * count;
  }
  problem_.rhs(t, first, count, y_hat.data(), f_hat.data());
  problem_.rhs(t, first, count, y, dydt);
  // f(t, y) + (ŷ′ − f(t, ŷ)): the source first, so that y = ŷ gives ŷ′ up to one rounding.
  for (int f = 0; f < fields; ++f)
    for (int i = 0; i < count; ++i) dydt[f][i] += trajectory_rates[f * count + i] - f_hat[static_cast<std::size_t>(f)][i];
}

State ManufacturedProblem::solution(Eigen::Index first, const State& initial, double tau) const {
  State at(initial.rows(), initial.cols());
  double rate = 0.0;
  for (int f = 0; f < static_cast<int>(initial.cols()); ++f)
    for (Eigen::Index i = 0; i < initial.rows(); ++i) trajectory(first + i, f, tau, at(i, f), rate);
  return at;
}

std::string ManufacturedProblem::formula() const {
  return "manufactured: y' = f(t, y) + yhat'(t) - f(t, yhat(t)), yhat = y0 exp(A [sin(w t + theta) - sin theta]) "
         "(A = 0.1, w = 2 pi/" + number(duration_) + " (1 + frac(p phi)/2)); docs/verification.md";
}

nlohmann::json ManufacturedProblem::parameters() const {
  nlohmann::json j = case_parameters(problem_);
  j["manufactured"] = {{"amplitude", kManufacturedAmplitude}, {"duration", duration_}};
  return j;
}

void ManufacturedProblem::linear_decay(Eigen::Index first, int count, double* const* lambda) const {
  problem_.capability<LinearDecay>()->linear_decay(first, count, lambda);
}

double ManufacturedProblem::time_scale(Eigen::Index member, const double* y, double tau) const {
  return std::min(dlpverify::time_scale(problem_, member, y, tau), 1.0 / omega(member));
}

std::string ManufacturedProblem::time_unit() const {
  const TimeUnit* unit = problem_.capability<TimeUnit>();
  return unit ? unit->time_unit() : "s";
}

std::unique_ptr<Problem> make_manufactured(std::unique_ptr<const Problem> problem, double duration) {
  return std::make_unique<ManufacturedProblem>(std::move(problem), duration);
}

}  // namespace dlpverify
