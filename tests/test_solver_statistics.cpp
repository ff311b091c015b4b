// SolverStatistics (include/dlpverify/solver_statistics.hpp) in the reports' JSON: each typed
// count under the key the reports have always written, nothing for a count not reported, the
// extras beside them; read back to the same members; blocks' counts added member by member.
// The expected texts are written out here as the reports write them (nlohmann-json sorts keys).
#include <boost/test/unit_test.hpp>

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/solver_statistics.hpp"

namespace unit_solver_statistics {

using namespace dlpverify;

namespace {

// A CVODE Adams solve's statistics, as CvodeIntegrator fills them.
SolverStatistics cvode_like() {
  SolverStatistics s;
  s.steps = 100;
  s.rhs_evals = 130;
  s.error_test_failures = 3;
  s.nonlinear_iterations = 120;
  s.nonlinear_convergence_failures = 0;
  s.linear_solver_setups = 0;
  s.extras = {{"method", std::string("adams")}, {"rtol", 1e-6},          {"last_order", 5L},
              {"first_step", 1e-7},             {"last_step", 1e-4},     {"current_time", 0.002},
              {"warnings", 0L}};
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(solver_statistics)

BOOST_AUTO_TEST_CASE(writes_the_keys_the_reports_write) {
  BOOST_TEST(nlohmann::json(cvode_like()).dump() ==
             R"({"current_time":0.002,"error_test_failures":3,"first_step":1e-07,"last_order":5,"last_step":0.0001,)"
             R"("linear_solver_setups":0,"method":"adams","nonlinear_convergence_failures":0,"nonlinear_iterations":120,)"
             R"("rhs_evals":130,"rtol":1e-06,"steps":100,"warnings":0})");
  SolverStatistics rk4;
  rk4.steps = 8;
  rk4.rhs_evals = 32;
  BOOST_TEST(nlohmann::json(rk4).dump() == R"({"rhs_evals":32,"steps":8})");
  // A count not reported writes no key; an absent extra (a contraction never measured) writes null.
  SolverStatistics staggered;
  staggered.steps = 4;
  staggered.extras = {{"contraction_min", StatisticValue{}}};
  BOOST_TEST(nlohmann::json(staggered).dump() == R"({"contraction_min":null,"steps":4})");
  BOOST_TEST(SolverStatistics{}.empty());
  BOOST_TEST(nlohmann::json(SolverStatistics{}).dump() == "{}");
  BOOST_TEST(!staggered.empty());
}

BOOST_AUTO_TEST_CASE(reads_back_what_it_wrote) {
  const std::string text =
      R"({"current_time":0.002,"error_test_failures":3,"first_step":1e-07,"last_order":5,"last_step":0.0001,)"
      R"("linear_solver_setups":0,"method":"adams","nonlinear_convergence_failures":0,"nonlinear_iterations":120,)"
      R"("rhs_evals":130,"rtol":1e-06,"steps":100,"warnings":0})";
  const SolverStatistics back = nlohmann::json::parse(text).get<SolverStatistics>();
  BOOST_TEST(back.steps.value() == 100);
  BOOST_TEST(back.rhs_evals.value() == 130);
  BOOST_TEST(back.error_test_failures.value() == 3);
  BOOST_TEST(!back.rhs_evals_jacobian.has_value());  // not in the text: not reported, not 0
  BOOST_TEST(!back.linear_iterations.has_value());
  BOOST_TEST(back.extra_count("last_order").value() == 5);
  BOOST_TEST(back.extra_real("rtol").value() == 1e-6);
  BOOST_TEST(std::get<std::string>(back.extras.at("method")) == "adams");
  BOOST_TEST(back.extras.count("steps") == 0u);  // a typed key is never an extra
  BOOST_TEST((back == cvode_like()));
  BOOST_TEST(nlohmann::json(back).dump() == text);
  // A typed count that is not an integer is refused, not read as 0.
  BOOST_CHECK_THROW(nlohmann::json::parse(R"({"steps":1.5})").get<SolverStatistics>(), std::invalid_argument);
  BOOST_CHECK_THROW(nlohmann::json::parse(R"({"rhs_evals":"many"})").get<SolverStatistics>(), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(blocks_add_their_counts) {
  SolverStatistics total, a, b;
  a.steps = 10;
  a.rhs_evals = 14;
  a.extras = {{"method", std::string("adams")}};
  b.steps = 7;
  b.rhs_evals = 9;
  b.error_test_failures = 2;
  total += a;
  total += b;
  BOOST_TEST(total.steps.value() == 17);
  BOOST_TEST(total.rhs_evals.value() == 23);
  BOOST_TEST(total.error_test_failures.value() == 2);   // reported by one block
  BOOST_TEST(!total.nonlinear_iterations.has_value());  // reported by none
  BOOST_TEST(total.extras.empty());                     // a solve's description is not added
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_solver_statistics
