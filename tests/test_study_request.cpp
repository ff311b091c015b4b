// The study as one request (dlpverify/study_request.hpp), as an API user calls it: y' = −y²,
// y(0) = 1, whose closed form y = 1/(1 + t) is the reference, and whose global error for Heun's
// method and the midpoint rule has a leading constant in closed form (test_error_constant.cpp):
// |C| = T/(2(1 + T)³) = 1/16 for Heun and 3T/(4(1 + T)³) = 3/32 for the midpoint rule at T = 1.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "quadratic_decay.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/recorded_study.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/study_request.hpp"
#include "harness/distribution.hpp"

namespace unit_study_request {

using namespace dlpverify;

namespace {

using Quadratic = test::QuadraticDecay;

template <const auto& Tableau>
MakeIntegrator method(const char* name) {
  return [name](const Problem&) { return std::make_unique<ExplicitRungeKutta<Tableau>>(name); };
}

// Δt = 1/64 … 1/1024 to T = 1 against the closed form, judged against order `order`.
StudyRequest request(const Problem& problem, MakeIntegrator make, double order) {
  StudyRequest r;
  r.problem = &problem;
  r.make_integrator = std::move(make);
  r.plan.t_end = 1.0;
  r.plan.coarsest_dt = 1.0 / 64.0;
  r.plan.levels = 5;
  r.plan.expected_order = order;
  r.check.emplace();
  r.check->order = order;
  return r;
}

// What run() refuses `r` for, as "quantity = value"; "none" when it runs.
std::string refusal(const StudyRequest& r) {
  try {
    run(r);
  } catch (const InputError& e) {
    return e.quantity() + " = " + e.value();
  }
  return "none";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(study_request)

// Heun is of order 2: the check passes, and the constant is the closed form's 1/16 (within 1.5%,
// the next term's share at these steps, test_error_constant.cpp).
BOOST_AUTO_TEST_CASE(a_method_of_its_order_passes) {
  const Quadratic problem;
  const StudyOutcome outcome = run(request(problem, method<tableau::heun>("heun"), 2.0));
  BOOST_REQUIRE(outcome.reported);
  BOOST_REQUIRE(outcome.verdict);
  BOOST_TEST(outcome.verdict->passed());
  BOOST_TEST(outcome.exit_code() == kExitDone);
  BOOST_TEST(outcome.description.integrator == "heun");
  BOOST_TEST(outcome.result.levels.size() == 5u);
  BOOST_TEST(std::abs(outcome.result.orders[0].constant.value / (1.0 / 16.0) - 1.0) < 0.015);
  BOOST_TEST(!outcome.report.contains("missed_order"));
}

// Expected order 3 of an order-2 method: the check fails, exit 1, and the table and the report say
// so (a clean order 2 shows no reason beyond the order itself).
BOOST_AUTO_TEST_CASE(a_missed_order_fails_with_its_reasons) {
  const Quadratic problem;
  const StudyOutcome outcome = run(request(problem, method<tableau::heun>("heun"), 3.0));
  BOOST_REQUIRE(outcome.verdict);
  BOOST_TEST(!outcome.verdict->passed());
  BOOST_TEST(outcome.verdict->has(CheckOutcome::order_miss));
  BOOST_TEST(outcome.exit_code() == kExitCheckFailed);
  BOOST_TEST(outcome.report.contains("missed_order"));
  BOOST_TEST(outcome.table.find("y: FAIL, fitted order 2.0") != std::string::npos);
}

// The baseline gate through the request: the midpoint rule's constant, 3/32, is 1.5 times Heun's
// 1/16, outside a 5% band around it, though both are of order 2.
BOOST_AUTO_TEST_CASE(a_baseline_gates_the_error_constant) {
  const Quadratic problem;
  const StudyOutcome heun = run(request(problem, method<tableau::heun>("heun"), 2.0));
  StudyRequest midpoint = request(problem, method<tableau::midpoint>("midpoint"), 2.0);
  midpoint.check->baseline = read_recorded_study(heun.report, "heun.json", "baseline");
  const StudyOutcome outcome = run(midpoint);
  BOOST_REQUIRE(outcome.verdict);
  BOOST_TEST(outcome.verdict->has(CheckOutcome::order_within));
  BOOST_TEST(outcome.verdict->has(CheckOutcome::constant_outside));
  BOOST_TEST(!outcome.verdict->passed());

  StudyRequest again = request(problem, method<tableau::heun>("heun"), 2.0);
  again.check->baseline = read_recorded_study(heun.report, "heun.json", "baseline");
  const StudyOutcome same = run(again);
  BOOST_TEST(same.verdict->has(CheckOutcome::constant_within));
  BOOST_TEST(same.verdict->passed());
}

// A progress that asks to stop stops the study before its first level.
BOOST_AUTO_TEST_CASE(a_stop_between_levels_throws_study_stopped) {
  const Quadratic problem;
  StudyProgress progress;
  progress.stop = [] { return true; };
  BOOST_CHECK_THROW(run(request(problem, method<tableau::heun>("heun"), 2.0), progress), StudyStopped);
}

// A request no study can run is refused before any work, naming the quantity in the API's words:
// zero levels, one level without a search, a step, duration or ratio out of its domain, steps
// that are not whole, a search's rules out of theirs. One level starts a search.
BOOST_AUTO_TEST_CASE(a_request_no_study_can_run_is_refused_by_its_quantity) {
  const Quadratic problem;
  int made = 0;
  const MakeIntegrator counted = [&made](const Problem&) {
    ++made;
    return std::make_unique<ExplicitRungeKutta<tableau::heun>>("heun");
  };
  const StudyRequest good = request(problem, counted, 2.0);
  std::vector<std::pair<std::function<void(StudyRequest&)>, std::string>> cases = {
      {[](StudyRequest& r) { r.plan.levels = 0; }, "levels = 0"},
      {[](StudyRequest& r) { r.plan.levels = 1; }, "levels = 1"},
      {[](StudyRequest& r) { r.plan.levels = 31; }, "levels = 31"},
      {[](StudyRequest& r) { r.plan.coarsest_dt = 0.0; }, "time step = 0"},
      {[](StudyRequest& r) { r.plan.coarsest_dt = 0.3; }, "time step = 0.3"},
      {[](StudyRequest& r) { r.plan.t_end = -1.0; }, "duration = -1"},
      {[](StudyRequest& r) { r.plan.ratio = 1.0; }, "step ratio = 1"},
      {[](StudyRequest& r) { r.plan.ratio = 1.3; }, "step ratio = 1.3"},
      {[](StudyRequest& r) { r.problem = nullptr; }, "study = incomplete"},
      {[](StudyRequest& r) { r.reference.rtol = 1e-3; }, "reference relative tolerance = 0.001"},
      {[](StudyRequest& r) { r.reference.rtol = 1e-15; }, "reference relative tolerance = 1e-15"},
      {[](StudyRequest& r) { r.reference.max_steps = 0; }, "CVODE step limit = 0"},
      {[](StudyRequest& r) { r.search.emplace().budget_seconds = 0.0; }, "level search budget = 0"},
      {[](StudyRequest& r) { r.search.emplace().order_half_width = 2.0; }, "order interval half-width = 2"},
      {[](StudyRequest& r) { r.search.emplace().min_fit_levels = 1; }, "fitted levels = 1"},
      {[](StudyRequest& r) { r.search.emplace().max_levels = 40; }, "level limit = 40"},
  };
  for (const auto& [spoil, expected] : cases) {
    StudyRequest bad = good;
    spoil(bad);
    BOOST_TEST(refusal(bad) == expected);
  }
  BOOST_TEST(made == 0, "no integrator was made for a refused request");
  StudyRequest search = good;
  search.plan.levels = 1;
  search.search.emplace().budget_seconds = 1e7;
  BOOST_TEST(refusal(search) == "none", "one level starts a search");
}

// Rank 0 of two, every exchange its own values (no rank is asked for anything before the refusal).
struct TwoRanks : Distribution {
  int rank() const override { return 0; }
  int ranks() const override { return 2; }
  std::vector<double> all_gathered(const std::vector<double>& local) const override { return local; }
  State gathered_on_root(const State& local) const override { return local; }
  std::string from_root(const std::string& text) const override { return text; }
};

// Under mpirun a request whose integrator steps the whole population at once is refused before
// any level, naming the integrator; so is a manufactured reference, and an integrator reference
// that does not step each member alone. Serially the same request runs.
BOOST_AUTO_TEST_CASE(under_mpirun_what_steps_the_whole_population_is_refused) {
  const Quadratic problem;
  StudyRequest whole = request(problem, method<tableau::heun>("heun"), 2.0);
  BOOST_TEST((whole.reach == IntegratorReach::whole_population), "the default claims nothing");
  BOOST_TEST(run(whole).verdict->passed(), "serially any reach runs");

  const TwoRanks two;
  install_distribution(&two);
  const std::unique_ptr<const TwoRanks, void (*)(const TwoRanks*)> serial_again(
      &two, [](const TwoRanks*) { install_distribution(nullptr); });  // also when a check throws
  BOOST_TEST(refusal(whole) == "integrator = heun");
  StudyRequest reference = whole;
  reference.reach = IntegratorReach::each_member;
  reference.reference.kind = ReferenceKind::manufactured;
  BOOST_TEST(refusal(reference) == "reference = manufactured");
  reference.reference.kind = ReferenceKind::integrator;
  reference.reference.integrator = std::make_shared<ExplicitRungeKutta<tableau::rk4>>("rk4");
  reference.reference.dt = 1.0 / 128.0;
  reference.reference.integrator_reach = IntegratorReach::across_ranks;
  BOOST_TEST(refusal(reference) == "reference = integrator:rk4");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_study_request
