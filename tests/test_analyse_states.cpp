// A study of states computed elsewhere (analyse_states, `dlpverify analyze`): states with an error
// of exactly C Δt^p have closed-form norms, orders and Richardson estimates.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "dlpverify/errors.hpp"
#include "dlpverify/study.hpp"

namespace unit_analyse_states {

using namespace dlpverify;
namespace tt = boost::test_tools;

namespace {

constexpr int kLevels = 5;
const double kSizeOfC = std::sqrt(1.0 + 4.0 + 9.0 + 16.0);  // ‖C‖ over the four members, C_p = p + 1

// t_end = 1, Δt_k = 0.1 / 2^k: 10 … 160 steps; one field x, variable "x".
StudyPlan plan() {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.ratio = 2.0;
  plan.levels = kLevels;
  plan.expected_order = 2.0;
  plan.variables = {{"x", 0, 1, "m"}};
  return plan;
}

State exact() {
  State y(4, 1);
  y << 1.0, -2.0, 3.0, 0.5;
  return y;
}

// y_k = y + C Δt_k², C_p = p + 1: the error of a second-order method, with no higher terms.
std::vector<State> states() {
  std::vector<State> all;
  for (int k = 0; k < kLevels; ++k) {
    const double dt = 0.1 / std::pow(2.0, k);
    State y = exact();
    for (int p = 0; p < 4; ++p) y(p, 0) += (p + 1) * dt * dt;
    all.push_back(y);
  }
  return all;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(analyse_states)

BOOST_AUTO_TEST_CASE(against_a_reference_every_state_is_a_level) {
  const State reference = exact();
  const StudyResult r = dlpverify::analyse_states(plan(), states(), &reference, {0.0});
  BOOST_TEST(r.levels.size() == 5u);
  BOOST_TEST(!r.against_next_level);
  for (int k = 0; k < kLevels; ++k) {
    const double dt = 0.1 / std::pow(2.0, k);
    BOOST_TEST(r.levels[k].steps == 10L << k);
    BOOST_TEST(r.levels[k].norms[0].l2 == kSizeOfC * dt * dt, tt::tolerance(1e-12));  // ‖C‖ Δt²
  }
  BOOST_TEST(r.orders[0].fit.value == 2.0, tt::tolerance(1e-10));
  BOOST_TEST(r.reference.trusted);
}

BOOST_AUTO_TEST_CASE(without_a_reference_each_level_is_measured_against_the_next) {
  const StudyResult r = dlpverify::analyse_states(plan(), states(), nullptr, {});
  BOOST_TEST(r.against_next_level);
  BOOST_TEST(r.levels.size() == 4u);  // the finest state is the last level's reference
  for (int k = 0; k < kLevels - 1; ++k) {
    const double dt = 0.1 / std::pow(2.0, k);
    // y_k − y_{k+1} = C (Δt_k² − Δt_k²/4) = ¾ C Δt_k²
    BOOST_TEST(r.levels[k].norms[0].l2 == 0.75 * kSizeOfC * dt * dt, tt::tolerance(1e-12));
  }
  BOOST_TEST(r.orders[0].fit.value == 2.0, tt::tolerance(1e-10));
  // Self-convergence over all five states; Richardson's d/(r^p − 1) is exact for an error C Δt^p:
  // the finest state's error ‖C‖ Δt_4².
  const SelfConvergence& s = r.self_convergence[0];
  BOOST_TEST(s.difference.size() == 5u);
  BOOST_TEST(*s.order.back() == 2.0, tt::tolerance(1e-10));
  const double finest_dt = 0.1 / 16.0;
  BOOST_TEST(*s.richardson_error == kSizeOfC * finest_dt * finest_dt, tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(a_plan_of_other_levels_is_refused) {
  StudyPlan three = plan();
  three.levels = 3;
  BOOST_CHECK_THROW(dlpverify::analyse_states(three, states(), nullptr, {}), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_analyse_states
