// evaluate_rhs (dlpverify/evaluate_rhs.hpp) against a hand computation on a problem of the test's
// own whose rates differ per member and depend on t: a block handed the wrong first member (an
// offset slip) gets another member's rates, a block cut short leaves members' rates unset, and a
// thread count that changed any bit of the result would show in the comparison of 1 and 3 threads.
#include <boost/test/unit_test.hpp>

#include <omp.h>

#include <cmath>
#include <limits>
#include <string>

#include "dlpverify/errors.hpp"
#include "dlpverify/evaluate_rhs.hpp"
#include "dlpverify/runge_kutta.hpp"

namespace unit_evaluate_rhs {

using namespace dlpverify;

namespace {

// Two fields per member p of N, with λ_p = 1 + p/N:
//   dy0/dt = −λ_p y0 + t y1,   dy1/dt = λ_p y0 y1.
class Rates final : public Problem {
 public:
  explicit Rates(Eigen::Index members) : members_(members) {}
  std::string name() const override { return "rates"; }
  std::vector<Field> fields() const override { return {{"y0", "1"}, {"y1", "1"}}; }
  Eigen::Index members() const override { return members_; }
  State initial_state() const override { return state(); }
  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) {
      const double lambda = 1.0 + static_cast<double>(first + i) / static_cast<double>(members_);
      dydt[0][i] = -lambda * y[0][i] + t * y[1][i];
      dydt[1][i] = lambda * y[0][i] * y[1][i];
    }
  }
  // A state that differs per member and per field.
  State state() const {
    State y(members_, 2);
    for (Eigen::Index p = 0; p < members_; ++p) {
      y(p, 0) = 0.5 + std::sin(static_cast<double>(p));
      y(p, 1) = 2.0 + std::cos(3.0 * static_cast<double>(p));
    }
    return y;
  }

 private:
  Eigen::Index members_;
};

// The rates of the problem's formula, member by member (written out here, not through rhs).
State by_hand(Eigen::Index n, double t, const State& y) {
  State rates(n, 2);
  for (Eigen::Index p = 0; p < n; ++p) {
    const double lambda = 1.0 + static_cast<double>(p) / static_cast<double>(n);
    rates(p, 0) = -lambda * y(p, 0) + t * y(p, 1);
    rates(p, 1) = lambda * y(p, 0) * y(p, 1);
  }
  return rates;
}

// Bitwise equality of two N × F arrays, naming the first difference.
void check_identical(const State& actual, const State& expected) {
  BOOST_REQUIRE_EQUAL(actual.rows(), expected.rows());
  BOOST_REQUIRE_EQUAL(actual.cols(), expected.cols());
  for (Eigen::Index f = 0; f < actual.cols(); ++f)
    for (Eigen::Index p = 0; p < actual.rows(); ++p)
      if (!(actual(p, f) == expected(p, f))) {
        BOOST_ERROR("member " << p << " field " << f << ": " << actual(p, f) << " != " << expected(p, f));
        return;
      }
}

// Rates whose right-hand side fails for one member, as a user's may (a domain error, a table
// lookup out of range).
class FailsAtOneMember final : public Problem {
 public:
  explicit FailsAtOneMember(Eigen::Index members) : members_(members) {}
  std::string name() const override { return "fails"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  Eigen::Index members() const override { return members_; }
  State initial_state() const override { return State::Ones(members_, 1); }
  void rhs(double, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) {
      if (first + i == members_ - 3) throw SolverError("member " + std::to_string(first + i) + " left its domain");
      dydt[0][i] = -y[0][i];
    }
  }

 private:
  Eigen::Index members_;
};

}  // namespace

BOOST_AUTO_TEST_SUITE(evaluate_rhs)

// N = 7·256 + 209: eight blocks (enough to share over threads), the last one short.
BOOST_AUTO_TEST_CASE(every_member_gets_its_own_rates) {
  const Eigen::Index n = 7 * kRhsBlock + 209;
  const Rates problem(n);
  const State y = problem.state();
  State rates = State::Constant(3, 1, std::numeric_limits<double>::quiet_NaN());  // of another shape: resized
  dlpverify::evaluate_rhs(problem, 0.75, y, rates);
  check_identical(rates, by_hand(n, 0.75, y));
}

// Fewer members than one block: one call.
BOOST_AUTO_TEST_CASE(a_population_smaller_than_a_block) {
  const Rates problem(5);
  const State y = problem.state();
  State rates;
  dlpverify::evaluate_rhs(problem, -2.0, y, rates);
  check_identical(rates, by_hand(5, -2.0, y));
}

BOOST_AUTO_TEST_CASE(bit_identical_for_one_and_three_threads) {
  const Eigen::Index n = 11 * kRhsBlock + 3;
  const Rates problem(n);
  const State y = problem.state();
  const int threads = omp_get_max_threads();
  State one, three;
  omp_set_num_threads(1);
  dlpverify::evaluate_rhs(problem, 1.25, y, one);
  omp_set_num_threads(3);
  dlpverify::evaluate_rhs(problem, 1.25, y, three);
  omp_set_num_threads(threads);
  check_identical(three, one);
  check_identical(three, by_hand(n, 1.25, y));
}

BOOST_AUTO_TEST_CASE(a_state_of_another_shape_is_refused) {
  const Rates problem(10);
  State rates;
  BOOST_CHECK_THROW(dlpverify::evaluate_rhs(problem, 0.0, State::Zero(9, 2), rates), std::exception);
  BOOST_CHECK_THROW(dlpverify::evaluate_rhs(problem, 0.0, State::Zero(10, 1), rates), std::exception);
}

// An exception of a problem's right-hand side leaves evaluate_rhs and a Runge–Kutta step as
// itself, on 1 and on 3 threads: it must not escape an OpenMP region, where the program would
// terminate (exit 134) instead of failing with the exit code of a solver failure.
BOOST_AUTO_TEST_CASE(a_failing_rhs_is_thrown_after_the_parallel_region) {
  const FailsAtOneMember problem(20 * kRhsBlock);
  const int threads = omp_get_max_threads();
  for (int t : {1, 3}) {
    omp_set_num_threads(t);
    State rates;
    BOOST_CHECK_EXCEPTION(dlpverify::evaluate_rhs(problem, 0.0, problem.initial_state(), rates), SolverError,
                          [&](const SolverError& e) {
                            return std::string(e.what()) == "member " + std::to_string(20 * kRhsBlock - 3) +
                                                                " left its domain";
                          });
    ExplicitRungeKutta<tableau::rk4> rk4("rk4");
    State y = problem.initial_state();
    BOOST_CHECK_THROW(rk4.advance(problem, y, 0.0, 0.1, 2), SolverError);
  }
  omp_set_num_threads(threads);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_evaluate_rhs
