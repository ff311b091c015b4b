#include "problems/thermal/adaptive_check.hpp"

#include <cmath>

#include "dlpverify/closed_form.hpp"
#include "integrators/implicit/member_norms.hpp"
#include "dlpverify/splitting.hpp"

namespace dlpverify::thermal {

namespace {

// max over members of ‖a − e‖/‖e‖, each field in units of its size.
double relative_error(const State& a, const State& e, const std::vector<double>& size) {
  const int fields = static_cast<int>(a.cols());
  return (implicit::member_norms(a, e, size, 0, fields) / implicit::member_norms(e, size, 0, fields)).maxCoeff();
}

}  // namespace

AdaptiveVerdict check_adaptive(const Problem& problem, const implicit::AdaptiveRun& run, const State& initial,
                               double duration, double tolerance, bool error_control) {
  const auto* coupled = problem.capability<SweepContraction>();
  AdaptiveVerdict v;
  v.error = has_closed_form(problem)
                ? relative_error(run.state, closed_form(problem, initial, duration), field_scales(problem, initial))
                : std::nan("");
  v.limit = coupled ? coupled->step_limit() : std::nan("");
  v.below_limit = !coupled || run.largest_step < v.limit;
  v.accurate = !error_control || std::isnan(v.error) || v.error <= 10.0 * tolerance;
  return v;
}

}  // namespace dlpverify::thermal
