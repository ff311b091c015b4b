// A study that chooses its own levels (dlpverify/level_search.hpp, docs/verification.md "Levels
// found by the study"), on hand-made errors e = A Δt^p against an exact reference (0, 1): the
// search stops on a narrow order interval as soon as it is fitted over min_fit_levels levels, and
// a start at the round-off floor is coarsened by the ratio, never refined.
#include <boost/test/unit_test.hpp>

#include <algorithm>

#include <cmath>
#include <string>
#include <vector>

#include "dlpverify/level_search.hpp"
#include "dlpverify/study.hpp"

namespace unit_level_search {

using namespace dlpverify;
namespace tt = boost::test_tools;

namespace {

// Levels from Δt_0 over t_end = 1 by the ratio 2, one variable y checked at order p.
StudyPlan plan_from(double coarsest_dt, double p) {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = coarsest_dt;
  plan.ratio = 2.0;
  plan.expected_order = p;
  plan.variables = {{"y", 0, 1, "1"}};
  return plan;
}

// A level's state (A Δt^p, 1): L2 error A Δt^p against (0, 1), solution size 1.
Solve power_law(double a, double p) {
  return [a, p](double dt, long, SolverStatistics&) {
    State y(2, 1);
    y << a * std::pow(dt, p), 1.0;
    return y;
  };
}

State exact_reference() {
  State reference(2, 1);
  reference << 0.0, 1.0;
  return reference;
}

bool starts_with(const std::string& text, const std::string& start) { return text.rfind(start, 0) == 0; }

}  // namespace

BOOST_AUTO_TEST_SUITE(level_search)

// e = Δt² from Δt_0 = 1/8, far above the round-off floor (at 1/128: e = 6.1e-5, floor
// ½ ε √128 = 1.3e-15, 15 levels away, more than floor_levels = 4): an exact power law has a
// fitted interval of width ~0 once it has three levels (two leave no interval). The search
// stops on the interval once it has held at two levels in a row, each with at least
// min_fit_levels levels and three pairwise orders (four levels) that settle: after
// max(min_fit_levels, 4) + 1 levels, for min_fit_levels = 3, 4 and 5.
BOOST_AUTO_TEST_CASE(narrow_with_exactly_min_fit_levels) {
  for (int min_fit_levels : {3, 4, 5}) {
    LevelSearchRules rules;
    rules.min_fit_levels = min_fit_levels;
    LevelSearch search;
    const StudyResult study =
        search_levels(plan_from(0.125, 2.0), exact_reference(), {0.0}, power_law(1.0, 2.0), rules, search);
    const auto levels = static_cast<std::size_t>(std::max(min_fit_levels, 4) + 1);
    BOOST_TEST(to_string(search.stop) == "order-interval", search.reason);
    BOOST_TEST(search.run.size() == levels, "min_fit_levels " << min_fit_levels);
    BOOST_TEST(study.levels.size() == levels);
    BOOST_TEST(study.orders[0].fit.levels.size() == levels);
    BOOST_TEST(study.orders[0].fit.value == 2.0, tt::tolerance(1e-12));
    BOOST_TEST_REQUIRE(search.settled.size() == 1u);
    BOOST_TEST(search.settled[0].find("over " + std::to_string(levels) + " levels") != std::string::npos,
               search.settled[0]);
  }
}

// e = 2^−10 Δt⁴ with Δt_k = 2^−k against the floor ½ ε √(2^k) = 2^(k/2 − 53): e / floor =
// 2^(43 − 4.5k), below 1 from k = 10. Started at Δt = 2^−10, both first levels (k = 10, 11) are at
// the floor: the start is coarsened to 2^−9 (k = 9 is 2^2.5 above its floor, in the asymptotic
// range). From there k = 10 is at the floor again with one asymptotic level, so the search
// coarsens by the second rule (the floor reached before three asymptotic levels) to 2^−8, again
// to 2^−7, where k = 7, 8, 9 give a narrow interval and refinement goes on to the floor at k = 10
// (predicted one level away). Twelve levels run, by hand:
//   10 11 | 9 10 11 | 8 9 10 | 7 8 9 10 (kept).
BOOST_AUTO_TEST_CASE(a_start_at_the_round_off_floor_is_coarsened) {
  LevelSearch search;
  const StudyResult study = search_levels(plan_from(std::ldexp(1.0, -10), 4.0), exact_reference(), {0.0},
                                          power_law(std::ldexp(1.0, -10), 4.0), LevelSearchRules{}, search);
  const std::vector<int> exponents{10, 11, 9, 10, 11, 8, 9, 10, 7, 8, 9, 10};
  BOOST_TEST_REQUIRE(search.run.size() == exponents.size());
  for (std::size_t i = 0; i < exponents.size(); ++i) {
    BOOST_TEST(search.run[i].dt == std::ldexp(1.0, -exponents[i]), "run " << i);
    BOOST_TEST(search.run[i].kept == (i >= 8), "run " << i);
  }
  for (std::size_t i : {0u, 1u})
    BOOST_TEST(starts_with(search.run[i].note, "the start is at the round-off floor"), search.run[i].note);
  for (std::size_t i = 2; i < 8; ++i)
    BOOST_TEST(starts_with(search.run[i].note, "the round-off floor was reached before three asymptotic levels"),
               search.run[i].note);
  BOOST_TEST(to_string(search.stop) == "round-off", search.reason);
  BOOST_TEST(study.plan.coarsest_dt == std::ldexp(1.0, -7));
  BOOST_TEST(study.levels.size() == 4u);
  BOOST_TEST(study.orders[0].fit.levels == std::vector<int>({0, 1, 2}), tt::per_element());
  BOOST_TEST(study.orders[0].fit.value == 4.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_level_search
