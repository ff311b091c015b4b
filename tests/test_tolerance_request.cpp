// A sweep of tolerances as one request (dlpverify/tolerance_request.hpp), as an API user calls it,
// with an "adaptive integrator" whose error is known exactly: y' = −y², y(0) = 1 to T = 1, whose
// closed form y = 1/(1 + t) is the reference, solved as y(T)·(1 + 3 rtol^E). Its relative error is
// 3 rtol^E, so the fitted exponent is E to round-off and e/rtol is 3 at E = 1.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "quadratic_decay.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/tolerance_request.hpp"
#include "dlpverify/work_precision.hpp"

namespace unit_tolerance_request {

using namespace dlpverify;

namespace {

SolveAtTolerance error_as_rtol_to_the(double exponent) {
  return [exponent](const Problem&, State& state, double t0, double duration, double rtol, SolverStatistics& statistics) {
    const double y0 = state(0, 0);
    state(0, 0) = y0 / (1.0 + y0 * (t0 + duration)) * (1.0 + 3.0 * std::pow(rtol, exponent));
    statistics.steps = 1;
  };
}

// rtol = 1e-3 … 1e-7, a decade apart, judged against E = 1 ± 0.25.
ToleranceRequest request(const Problem& problem, double exponent) {
  ToleranceRequest r;
  r.problem = &problem;
  r.integrator = "rtol^" + std::to_string(exponent);
  r.solve = error_as_rtol_to_the(exponent);
  r.rtols = tolerance_sweep(1e-3, 1e-7, 1);
  r.t_end = 1.0;
  r.check = ProportionalityExpectation{};
  return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tolerance_request)

BOOST_AUTO_TEST_CASE(an_error_proportional_to_rtol_passes) {
  const test::QuadraticDecay problem;
  const ToleranceOutcome outcome = run(request(problem, 1.0));
  BOOST_REQUIRE(outcome.reported);
  BOOST_REQUIRE(outcome.verdict);
  BOOST_TEST(outcome.verdict->passed());
  BOOST_TEST(outcome.exit_code() == kExitDone);
  BOOST_REQUIRE_EQUAL(outcome.study.runs.size(), 5u);
  BOOST_TEST(outcome.study.proportionality[0].exponent.value == 1.0, boost::test_tools::tolerance(1e-6));
  for (const double ratio : outcome.study.proportionality[0].error_over_tolerance)
    BOOST_TEST(ratio == 3.0, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(outcome.report.at("integrator") == "rtol^1.000000");
  BOOST_TEST(outcome.report.at("reference") == "exact");
  BOOST_TEST(outcome.table.find("case quadratic-decay · integrator rtol^1.000000 by tolerance") == 0u);
}

// e ∝ √rtol misses E = 1 by 0.5; an error that ignores rtol is said to.
BOOST_AUTO_TEST_CASE(an_error_off_its_exponent_fails) {
  const test::QuadraticDecay problem;
  const ToleranceOutcome half = run(request(problem, 0.5));
  BOOST_REQUIRE(half.verdict);
  BOOST_TEST(!half.verdict->passed());
  BOOST_TEST(half.exit_code() == kExitCheckFailed);
  BOOST_TEST(half.study.proportionality[0].exponent.value == 0.5, boost::test_tools::tolerance(1e-6));
  const ToleranceOutcome ignored = run(request(problem, 0.0));
  BOOST_TEST(!ignored.verdict->passed());
  BOOST_TEST(ignored.table.find("ignores its tolerance") != std::string::npos);
}

// A CVODE reference must be a decade tighter than the tightest run (1e-7): 1e-7 itself is refused
// before any solve, naming the quantity in the API's words.
BOOST_AUTO_TEST_CASE(a_reference_as_loose_as_the_runs_is_refused) {
  const test::QuadraticDecay problem;
  ToleranceRequest r = request(problem, 1.0);
  r.reference.kind = ReferenceKind::cvode;
  r.reference.rtol = 1e-7;
  try {
    run(r);
    BOOST_FAIL("a reference as loose as the tightest run was taken");
  } catch (const InputError& e) {
    BOOST_TEST(e.quantity() == "reference relative tolerance");
    BOOST_TEST(e.reason() == "must be at most the tightest rtol / 10 = 1e-08, or the tightest runs measure the reference against itself");
  }
  ToleranceRequest empty = request(problem, 1.0);
  empty.rtols.clear();
  BOOST_CHECK_THROW(run(empty), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_tolerance_request
