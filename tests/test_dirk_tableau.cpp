// Diagonally implicit tableaux from a file (docs/verification.md, "Your Butcher tableau"): read,
// their order conditions with the diagonal counted, and their linear stability against closed
// forms; every SUNDIALS DIRK table, written as a tableau file, reaches the order SUNDIALS' own
// checker (ARKodeButcherTable_CheckOrder) finds; ARKStep steps one to its closed form.
#include <boost/test/unit_test.hpp>

#include <arkode/arkode_butcher.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <cstdio>
#include <unistd.h>
#include <string>
#include <utility>
#include <vector>

#include "dlpverify/errors.hpp"
#include "integrators/sundials/arkode_dirk_integrator.hpp"
#include "integrators/sundials/arkode_dirk_tables.hpp"
#include "integrators/tableau/order_conditions.hpp"
#include "integrators/tableau/stability.hpp"
#include "integrators/tableau/tableau_file.hpp"
#include "integrators/tableau/tableau_integrator.hpp"
#include "integrators/tableau/tableau_report.hpp"
#include "quadratic_decay.hpp"

namespace unit_dirk_tableau {

using namespace dlpverify;

namespace {

// A tableau file's text for s stages from rows of A, b and c (17 significant digits: exact).
std::string toml_of(const std::string& name, int order, const std::vector<std::vector<double>>& a,
                    const std::vector<double>& b, const std::vector<double>& c) {
  const auto list = [](const std::vector<double>& v) {
    std::string text = "[";
    char number[40];
    for (std::size_t i = 0; i < v.size(); ++i) {
      std::snprintf(number, sizeof number, "%.17g", v[i]);
      text += (i ? ", " : "") + std::string(number);
    }
    return text + "]";
  };
  std::string text = "name = \"" + name + "\"\norder = " + std::to_string(order) + "\nc = " + list(c) + "\nb = " + list(b) +
                     "\nA = [";
  for (std::size_t i = 0; i < a.size(); ++i) text += (i ? ", " : "") + list(a[i]);
  return text + "]\n";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(dirk_tableau)

// Closed forms (Hairer & Wanner, Solving ODEs II, §IV.3): backward Euler R = 1/(1 − z), L-stable;
// the implicit midpoint rule and the trapezoid as an ESDIRK (a singular A) R = (1 + z/2)/(1 − z/2),
// A-stable with |R(∞)| = 1; Alexander's two-stage SDIRK (γ = 1 − 1/√2) is order 2 and L-stable.
BOOST_AUTO_TEST_CASE(stability_against_closed_forms) {
  const TableauStability euler = tableau_stability(parse_tableau(toml_of("be", 1, {{1.0}}, {1.0}, {1.0}), "be"));
  BOOST_TEST(euler.r_infinity == 0.0);
  BOOST_TEST(euler.l_stable);
  for (const RuntimeTableau& t : {parse_tableau(toml_of("im", 2, {{0.5}}, {1.0}, {0.5}), "im"),
                                  parse_tableau(toml_of("tr", 2, {{0.0, 0.0}, {0.5, 0.5}}, {0.5, 0.5}, {0.0, 1.0}), "tr")}) {
    const TableauStability st = tableau_stability(t);
    BOOST_TEST(st.r_infinity == 1.0, boost::test_tools::tolerance(1e-8));
    BOOST_TEST(st.a_stable, t.source);
    BOOST_TEST(!st.l_stable, t.source);
    BOOST_TEST(st.max_on_axis == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(check_tableau(t).order == 2, t.source);
  }
  const double g = 1.0 - 1.0 / std::sqrt(2.0);
  const RuntimeTableau alexander =
      parse_tableau(toml_of("alexander", 2, {{g, 0.0}, {1.0 - g, g}}, {1.0 - g, g}, {g, 1.0}), "alexander");
  BOOST_TEST(alexander.implicit());
  BOOST_TEST(check_tableau(alexander).order == 2);
  BOOST_TEST(tableau_stability(alexander).l_stable);
  // A negative diagonal entry puts a pole in the left half-plane: not A-stable.
  BOOST_TEST(!tableau_stability(parse_tableau(toml_of("neg", 1, {{-0.5}}, {1.0}, {-0.5}), "neg")).a_stable);
}

// Every SUNDIALS DIRK table as a tableau file: read, and its order by the conditions here is the
// one SUNDIALS' checker finds (both up to 6; ours up to the claimed order + 1). Cash's two tables,
// which SUNDIALS stores to 11–12 digits, hold their conditions to 1.5e-11 only: met to the digits
// the table keeps (below 1e-10 of each sum), not to round-off, and the verdict says so.
BOOST_AUTO_TEST_CASE(sundials_dirk_tables_agree_with_sundials_checker) {
  BOOST_TEST(arkode_dirk_tables().size() == 23u);
  int stored_short = 0;
  for (const ArkodeTableInfo& info : arkode_dirk_tables()) {
    const sun::ButcherTable table = load_arkode_dirk_table(info.name);
    const int s = table->stages;
    std::vector<std::vector<double>> a(static_cast<std::size_t>(s), std::vector<double>(static_cast<std::size_t>(s)));
    std::vector<double> b(static_cast<std::size_t>(s)), c(static_cast<std::size_t>(s));
    for (int i = 0; i < s; ++i) {
      b[static_cast<std::size_t>(i)] = table->b[i];
      c[static_cast<std::size_t>(i)] = table->c[i];
      for (int j = 0; j < s; ++j) a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = table->A[i][j];
    }
    const RuntimeTableau t = parse_tableau(toml_of(info.name, table->q, a, b, c), info.name);
    int q = 0, p = 0;
    ARKodeButcherTable_CheckOrder(table.get(), &q, &p, nullptr);
    const TableauCheck check = check_tableau(t);
    if (info.name.rfind("ARKODE_CASH_", 0) == 0) {
      ++stored_short;
      const TableauVerdict verdict = judge_tableau(t);
      BOOST_TEST(verdict.passed, info.name);
      BOOST_TEST(verdict.report["conditions_met_to_digits"].get<int>() > 0, info.name);
      BOOST_TEST(verdict.table.find("only to the digits the table keeps") != std::string::npos, verdict.table);
    }
    BOOST_TEST(check.order == std::min(q, check.max_order),
               info.name << ": ours " << check.order << ", SUNDIALS " << q << "; "
                         << (check.failed_claims().empty() ? std::string() : check.failed_claims().front()->failure()));
    BOOST_TEST(t.implicit(), info.name);
  }
  BOOST_TEST(stored_short == 2);
}

// R(z) against closed forms: RK4's 1 + z + z²/2 + z³/6 + z⁴/24, backward Euler's 1/(1 − z); the
// grid of a stability region figure holds |R| at its points, and RK4's region reaches −2.785 on the
// real axis (|R(−2.785)| < 1 < |R(−2.786)|; Hairer & Wanner, Solving ODEs I, §IV.2).
BOOST_AUTO_TEST_CASE(stability_function_against_closed_forms) {
  const RuntimeTableau rk4 = parse_tableau(toml_of("rk4", 4, {{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}},
                                                   {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}, {0, 0.5, 0.5, 1}),
                                           "rk4");
  const RuntimeTableau euler = parse_tableau(toml_of("be", 1, {{1.0}}, {1.0}, {1.0}), "be");
  for (const std::complex<double> z : {std::complex<double>(-1.5, 0.7), std::complex<double>(0.3, -2.0)}) {
    const std::complex<double> taylor = 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
    BOOST_TEST(std::abs(stability_function(rk4, z) - taylor) <= 1e-14 * std::abs(taylor));
    BOOST_TEST(std::abs(stability_function(euler, z) - 1.0 / (1.0 - z)) <= 1e-15);
  }
  BOOST_TEST(std::abs(stability_function(rk4, -2.785)) < 1.0);
  BOOST_TEST(std::abs(stability_function(rk4, -2.786)) > 1.0);
  const std::vector<std::vector<double>> grid = stability_grid(rk4, 10.0, 5);
  BOOST_TEST(grid.size() == 25u);
  BOOST_TEST(grid[0][0] == -10.0);
  BOOST_TEST(grid[0][1] == -10.0);
  BOOST_TEST(grid[12][0] == 0.0);
  BOOST_TEST(grid[12][2] == 1.0);  // |R(0)| = 1
  BOOST_TEST(grid[1][0] == -5.0);  // Re z varies fastest
}

// The explicit block stepper takes explicit tableaux only: a DIRK tableau given to it is refused,
// naming A (make_tableau_integrator steps one through ARKStep instead).
BOOST_AUTO_TEST_CASE(the_explicit_stepper_refuses_an_implicit_tableau) {
  const RuntimeTableau t = parse_tableau(toml_of("im", 2, {{0.5}}, {1.0}, {0.5}), "im.toml");
  BOOST_CHECK_EXCEPTION(TableauIntegrator integrator(t), InputError,
                        [](const InputError& e) { return e.quantity() == "tableau im.toml: A[1][1]" && e.value() == "0.5"; });
}

// ARKStep with the user's DIRK table and its Newton iteration against closed forms of the steps
// themselves: on y' = λy (λ = −3, Δt = 0.1, ten steps) backward Euler gives (1/(1 − z))¹⁰ y₀ and
// the implicit midpoint rule ((1 + z/2)/(1 − z/2))¹⁰ y₀ and Alexander's SDIRK (γ = 1 − 1/√2)
// ((1 + (1 − 2γ) z)/(1 − γz)²)¹⁰ y₀, z = λΔt; on y' = −y² one implicit
// midpoint step solves z = y₀ − (Δt/2) z² for its stage, z = (√(1 + 2Δt y₀) − 1)/Δt, and lands on
// 2z − y₀. The Newton tolerance stated (kNewtonRelative, kNewtonTolerance) is met: every result
// agrees to 1e-11 of the state, far below the steps' own errors (1e-3 to 1e-5 here).
BOOST_AUTO_TEST_CASE(arkstep_steps_a_dirk_table_to_its_closed_form) {
  const double lambda = -3.0, dt = 0.1, z = lambda * dt, gamma = 1.0 - 1.0 / std::sqrt(2.0);
  const test::LinearDecay linear(lambda);
  const std::vector<std::pair<DirkTable, double>> cases{
      {DirkTable{{1.0}, {1.0}, {{1.0}}}, std::pow(1.0 / (1.0 - z), 10)},
      {DirkTable{{0.5}, {1.0}, {{0.5}}}, std::pow((1.0 + z / 2) / (1.0 - z / 2), 10)},
      {DirkTable{{gamma, 1.0}, {1.0 - gamma, gamma}, {{gamma, 0.0}, {1.0 - gamma, gamma}}},
       std::pow((1.0 + (1.0 - 2.0 * gamma) * z) / ((1.0 - gamma * z) * (1.0 - gamma * z)), 10)}};
  for (const auto& [table, exact] : cases) {
    ArkodeDirkIntegrator integrator("dirk", 1, table);
    State y = State::Constant(1, 1, 1.0);
    integrator.advance(linear, y, 0.0, dt, 10);
    BOOST_TEST(y(0, 0) == exact, boost::test_tools::tolerance(1e-11));
    BOOST_TEST(integrator.statistics().steps.value_or(-1) == 10);
    BOOST_TEST(integrator.statistics().nonlinear_convergence_failures.value_or(-1) == 0);
  }
  const test::QuadraticDecay quadratic;
  ArkodeDirkIntegrator midpoint("implicit midpoint", 2, DirkTable{{0.5}, {1.0}, {{0.5}}});
  State y = State::Constant(1, 1, 1.0);
  midpoint.advance(quadratic, y, 0.0, dt, 1);
  const double stage = (std::sqrt(1.0 + 2.0 * dt) - 1.0) / dt;
  BOOST_TEST(y(0, 0) == 2.0 * stage - 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(y(0, 0) - 1.0 / (1.0 + dt)) > 1e-5);  // the step's own error, for scale
}

// A diagonally implicit file that misses a condition warns as an explicit one does: one line at
// its first step, none before (bad input found first stays the only line); the integrator is
// ARKStep's, with its statistics. Alexander's SDIRK with b_2 + 1e-3 misses Σ b_i = 1.
BOOST_AUTO_TEST_CASE(a_slipped_dirk_file_warns_at_its_first_step) {
  const double gamma = 1.0 - 1.0 / std::sqrt(2.0);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("dlpverify-slipped-dirk-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << toml_of("slipped", 2, {{gamma, 0.0}, {1.0 - gamma, gamma}}, {1.0 - gamma, gamma + 1e-3}, {gamma, 1.0});
  std::ostringstream warnings;
  const std::unique_ptr<Integrator> integrator = make_tableau_integrator(file.string(), warnings);
  BOOST_TEST(warnings.str().empty());
  const test::LinearDecay linear(-3.0);
  State y = State::Constant(1, 1, 1.0);
  integrator->advance(linear, y, 0.0, 0.1, 10);
  integrator->advance(linear, y, 1.0, 0.1, 10);
  BOOST_TEST(warnings.str() == "dlpverify: warning: tableau " + file.string() + ": order 1: Σ b_i = 1 but is 1.001 (residual 0.001) (and 1 more; dlpverify tableau lists them)\n");
  BOOST_TEST(integrator->name() == "tableau:" + file.string());
  BOOST_TEST(integrator->order() == 2);
  BOOST_TEST(integrator->statistics().steps.value_or(-1) == 10);  // of the last advance
  std::filesystem::remove(file);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_dirk_tableau
