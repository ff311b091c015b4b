// A work-precision study as one request (dlpverify/precision_request.hpp), as an API user calls it:
// y' = −y², y(0) = 1 to T = 1 against its closed form y = 1/(1 + t). The adaptive method is the
// closed form with a relative error of exactly rtol; the fixed-step one is Heun's method, whose
// error at T = 1 is (1/16) Δt² to leading order (test_error_constant.cpp).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <memory>

#include "quadratic_decay.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/precision_request.hpp"
#include "dlpverify/runge_kutta.hpp"

namespace unit_precision_request {

using namespace dlpverify;

namespace {

void off_by_rtol(const Problem&, State& state, double t0, double duration, double rtol, SolverStatistics& statistics) {
  state(0, 0) = state(0, 0) / (1.0 + state(0, 0) * (t0 + duration)) * (1.0 + rtol);
  statistics.steps = 1;
  statistics.rhs_evals = 1;
}

// rtol 1e-4 … 1e-6; Heun at Δt = 1/16, 1/32, 1/64.
PrecisionRequest request(const Problem& problem) {
  PrecisionRequest r;
  r.problem = &problem;
  r.adaptive = {{"exact-plus-rtol", off_by_rtol}};
  r.rtols = tolerance_sweep(1e-4, 1e-6, 1);
  r.fixed_step = "heun";
  r.make_fixed_step = [](const Problem&) { return std::make_unique<ExplicitRungeKutta<tableau::heun>>("heun"); };
  r.plan.t_end = 1.0;
  r.plan.coarsest_dt = 1.0 / 16.0;
  r.plan.levels = 3;
  return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(precision_request)

BOOST_AUTO_TEST_CASE(the_runs_reach_their_closed_form_errors) {
  const test::QuadraticDecay problem;
  const PrecisionRequest r = request(problem);
  const std::vector<std::string> labels = run_labels(r);
  BOOST_REQUIRE_EQUAL(labels.size(), 6u);
  BOOST_TEST(labels.front() == run_label("exact-plus-rtol", 1e-4, std::nullopt));
  BOOST_TEST(labels.back() == run_label("heun", std::nullopt, 1.0 / 64.0));
  const PrecisionOutcome outcome = run(r);
  BOOST_REQUIRE(outcome.reported);
  BOOST_REQUIRE_EQUAL(outcome.result.runs.size(), 6u);
  for (int i = 0; i < 3; ++i)  // relative error rtol exactly
    BOOST_TEST(outcome.result.runs[i].norms[0].relative / r.rtols[i] == 1.0, boost::test_tools::tolerance(1e-6));
  for (int i = 3; i < 6; ++i) {  // |e| ≈ Δt²/16, y(1) = 1/2: relative 2 × that, within 15% at Δt = 1/16
    const double dt = 1.0 / (16.0 * std::pow(2.0, i - 3));
    BOOST_TEST(outcome.result.runs[i].norms[0].relative / (dt * dt / 8.0) == 1.0, boost::test_tools::tolerance(0.15));
    BOOST_TEST(outcome.result.runs[i].rhs_evals == 2 * static_cast<long>(std::lround(1.0 / dt)));
  }
  BOOST_TEST(outcome.report.at("case") == "quadratic-decay");
  BOOST_TEST(outcome.table.find("heun") != std::string::npos);
}

// A CVODE reference as loose as a decade under the tightest rtol is the limit; looser is refused.
BOOST_AUTO_TEST_CASE(a_reference_as_loose_as_the_runs_is_refused) {
  const test::QuadraticDecay problem;
  PrecisionRequest r = request(problem);
  r.reference.kind = ReferenceKind::cvode;
  r.reference.rtol = 1e-6;
  BOOST_CHECK_THROW(run(r), InputError);
  r.make_fixed_step = nullptr;
  BOOST_CHECK_THROW(run(r), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_precision_request
