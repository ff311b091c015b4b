// The nodes c_i of every shipped tableau (docs/model.md §3). While every right-hand side ignores t,
// a node that is not the row sum Σ_j a_ij changes nothing — so this checks the nodes directly, for
// our tableaux and every ARKODE table the registry lists, and integrates a non-autonomous problem
// y' = λ e^(λt) whose closed form e^(λt) is met at the method's order only when the stages are
// taken at t + c_i Δt: on a quadrature y' = f(t) a Runge–Kutta method is the rule Σ b_i f(t + c_i Δt).
#include <boost/test/unit_test.hpp>

#include <arkode/arkode_butcher_erk.h>

#include <cmath>
#include <map>
#include <string>

#include "dlpverify/runge_kutta.hpp"
#include "integrators/sundials/arkode_erk_integrator.hpp"
#include "integrators/registry.hpp"
#include "sundials/sundials_support.hpp"

namespace unit_tableau_nodes {

using namespace dlpverify;

namespace {

template <int Stages>
void check_row_sums(const ButcherTableau<Stages>& tableau, const std::string& name) {
  for (int i = 0; i < Stages; ++i) {
    double row = 0.0;
    for (int j = 0; j < Stages; ++j) row += tableau.a[i][j];
    BOOST_TEST(tableau.c[i] == row, name << ": c_" << i << " = " << tableau.c[i] << ", row sum " << row);
  }
}

// y' = λ e^(λ t), one field, 40 members (a block of 32 and a partial one): y(t) = e^(λ t) from
// y(t0) = e^(λ t0). t0 = 0.3, so a stage taken at the time since t0 rather than at t is wrong too.
class Exponential final : public Problem {
 public:
  static constexpr double kRate = 2.0;  // λ [1/s]
  std::string name() const override { return "exponential-in-t"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  std::vector<Variable> variables() const override { return {{"y", 0, 1, "1"}}; }
  Eigen::Index members() const override { return 40; }
  double initial_time() const override { return 0.3; }
  State initial_state() const override { return State::Constant(40, 1, std::exp(kRate * 0.3)); }
  void rhs(double t, Eigen::Index, int count, const double* const*, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = kRate * std::exp(kRate * t);
  }
};

// Largest |y − e^(λ t_end)| over the members after `steps` steps to t0 + 1.
double error_after(Integrator& integrator, long steps) {
  const Exponential problem;
  State y = problem.initial_state();
  integrator.advance(problem, y, problem.initial_time(), 1.0 / static_cast<double>(steps), steps);
  return (y - std::exp(Exponential::kRate * (problem.initial_time() + 1.0))).abs().maxCoeff();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tableau_nodes)

// Butcher's row-sum condition c_i = Σ_j a_ij, exact in binary for our dyadic tableaux.
BOOST_AUTO_TEST_CASE(our_nodes_are_row_sums) {
  check_row_sums(tableau::euler, "euler");
  check_row_sums(tableau::midpoint, "rk2 (midpoint)");
  check_row_sums(tableau::heun, "heun");
  check_row_sums(tableau::rk4, "rk4");
}

// The same for every ARKODE table the registry offers, to the rounding of their decimal
// coefficients (a few ulp of the row's largest term).
BOOST_AUTO_TEST_CASE(arkode_nodes_are_row_sums) {
  int tables = 0;
  for (const ArkodeTableInfo& info : arkode_erk_tables()) {
    sun::ButcherTable table(ARKodeButcherTable_LoadERKByName(info.name.c_str()));
    BOOST_TEST_REQUIRE(table.get() != nullptr, info.name);
    BOOST_TEST(table->stages == info.stages, info.name);
    for (int i = 0; i < table->stages; ++i) {
      double row = 0.0, largest = 0.0;
      for (int j = 0; j < table->stages; ++j) {
        row += table->A[i][j];
        largest = std::max(largest, std::abs(table->A[i][j]));
      }
      BOOST_TEST(std::abs(table->c[i] - row) <= 8.0 * 2.2e-16 * std::max(largest, 1.0),
                 info.name << ": c_" << i << " = " << table->c[i] << ", row sum " << row);
    }
    ++tables;
  }
  BOOST_TEST(tables == 15);
}

// Every fixed-step integrator of the registry (ours and ARKODE's) on y' = λ e^(λt): the observed
// order log2(e(n) / e(2n)) is the tableau's, within 0.25. n per order keeps both errors in the
// asymptotic range and above round-off (measured: 0.99, 2.00, 2.99–3.19, 3.99–4.01, 4.88–5.00,
// 5.99, 7.96). A node off its row sum (or a stage taken at t instead of t + c_i Δt) turns the
// rule into a lower-order quadrature: the midpoint rule with c_2 = 0 is Euler's, order 1.
BOOST_AUTO_TEST_CASE(non_autonomous_problem_shows_the_order) {
  const std::map<int, long> steps{{1, 32}, {2, 16}, {3, 16}, {4, 8}, {5, 8}, {6, 4}, {8, 2}};
  int integrators = 0;
  for (const IntegratorInfo& info : known_integrators()) {
    if (info.order <= 0) continue;  // CVODE: variable order
    BOOST_TEST_CONTEXT(info.name) {
      BOOST_TEST_REQUIRE(steps.count(info.order) == 1u);
      const auto integrator = make_integrator(info.name);
      const long n = steps.at(info.order);
      const double coarse = error_after(*integrator, n), fine = error_after(*integrator, 2 * n);
      const double observed = std::log2(coarse / fine);
      BOOST_TEST_MESSAGE(info.name << ": order " << observed << " (tableau " << info.order << "), errors " << coarse
                                   << ", " << fine);
      BOOST_TEST(std::abs(observed - info.order) <= 0.25, "observed order " << observed);
      ++integrators;
    }
  }
  BOOST_TEST(integrators == 19);  // rk2, euler, heun, rk4 and the 15 ARKODE tables
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_tableau_nodes
