#include "references/closed_form_audit.hpp"

#include <algorithm>
#include <cmath>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "harness/compensated_sum.hpp"
#include "harness/ode_residual.hpp"

namespace dlpverify {

namespace {

constexpr double kCvodeRtol = 1e-12;
constexpr double kAuditedFractions[] = {0.25, 0.5, 1.0};  // τ = fraction × t_end

// Relative L2 distance over the members where the closed form is finite; the others are
// counted, so a published formula that breaks down for some members still shows its size.
double finite_relative_distance(const State& closed_form, const State& reference, const Variable& variable,
                                int& non_finite) {
  NeumaierSum difference, size;  // compensated, like the study's norms
  for (Eigen::Index p = 0; p < closed_form.rows(); ++p) {
    double d = 0.0, r = 0.0;
    bool finite = true;
    for (int f = variable.first_field; f < variable.first_field + variable.fields; ++f) {
      const double c = closed_form(p, f), e = reference(p, f);
      finite = finite && std::isfinite(c);
      d += (c - e) * (c - e);
      r += e * e;
    }
    if (!finite) {
      ++non_finite;
      continue;
    }
    difference.add(d);
    size.add(r);
  }
  return size.value() > 0.0 ? std::sqrt(difference.value() / size.value()) : std::sqrt(difference.value());
}

}  // namespace

BaselineAudit audit_closed_form(const Problem& sample, double t_end, const AuditThresholds& thresholds) {
  if (!has_closed_form(sample))
    throw InputError("case", sample.name(), "has no closed form to audit (its reference is CVODE)");
  BaselineAudit result;
  const State initial = sample.initial_state();
  result.particles = static_cast<int>(initial.rows());
  auto record = [&result](double value, double& largest) {
    if (std::isfinite(value))
      largest = std::max(largest, value);
    else
      ++result.non_finite;
  };
  ReferenceSettings cvode;
  cvode.kind = ReferenceKind::cvode;
  cvode.rtol = kCvodeRtol;
  cvode.restart_at_kinks = true;
  for (double fraction : kAuditedFractions) {
    const double tau = fraction * t_end;
    result.times.push_back(tau);
    const OdeResidual residual = ode_residual(sample, initial, tau);
    record(residual.max(), result.residual);
    result.non_finite += residual.non_finite;
    const State exact = sample.measured(closed_form(sample, initial, tau), tau);
    nlohmann::json statistics;
    const State reference = sample.measured(solve_with_cvode(sample, initial, 0.0, tau, cvode, statistics), tau);
    for (const Variable& v : sample.variables())
      record(finite_relative_distance(exact, reference, v, result.non_finite), result.cvode_distance);
  }
  result.passed = result.non_finite == 0 && result.residual <= thresholds.residual &&
                  result.cvode_distance <= thresholds.cvode_distance;
  return result;
}

}  // namespace dlpverify
