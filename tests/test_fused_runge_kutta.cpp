// Fused Runge–Kutta steps (dlpverify/fused_runge_kutta.hpp): the tableau's arithmetic on a linear
// test equation against its stability polynomial, and the DLP's fused steps against the same
// steps through the block right-hand side, bit for bit.
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "dlp_support.hpp"
#include "dlpverify/fused_runge_kutta.hpp"
#include "problems/dlp/case.hpp"

namespace unit_fused_runge_kutta {

using namespace dlpverify;
using namespace dlpverify::dlp;

namespace {

// y' = −λ y with λ in field 1 (inert: its rate is zero, so it is carried unchanged).
struct DecayLane {
  static constexpr int kFields = 2;
  static constexpr std::array<bool, kFields> kActive{true, false};
  void operator()(double /*t*/, const double* y, double* r) const {
    r[0] = -y[1] * y[0];
    r[1] = 0.0;
  }
};

// One step of an explicit method of s stages multiplies y by its stability polynomial R(z),
// z = −λΔt: Σ_{q ≤ s} z^q / q! for these tableaux (s = order ≤ 4).
double stability(int order, double z) {
  double r = 1.0, term = 1.0;
  for (int q = 1; q <= order; ++q) r += (term *= z / q);
  return r;
}

template <const auto& Tableau>
void check_decay(int count) {
  constexpr int kBlock = 64;
  std::vector<double> y(kBlock, 0.0), lambda(kBlock, 0.0);
  for (int m = 0; m < count; ++m) {
    y[static_cast<std::size_t>(m)] = 1.0 + 0.01 * m;
    lambda[static_cast<std::size_t>(m)] = 1.0 + 3.0 * m;
  }
  const std::vector<double> y0 = y, lambda0 = lambda;
  double* fields[] = {y.data(), lambda.data()};
  const double dt = 0.01;
  const long steps = 12;
  fused_runge_kutta_steps<Tableau, DecayLane, kBlock>(DecayLane{}, fields, count, 0.0, dt, steps);
  for (int m = 0; m < count; ++m) {
    const auto i = static_cast<std::size_t>(m);
    const double expected = y0[i] * std::pow(stability(Tableau.order, -lambda0[i] * dt), static_cast<double>(steps));
    BOOST_TEST(std::abs(y[i] - expected) <= 1e-13 * std::abs(expected), "member " << m << ": " << y[i] << " vs " << expected);
    BOOST_TEST(lambda[i] == lambda0[i]);  // the inert field, untouched
  }
  for (int m = count; m < kBlock; ++m) BOOST_TEST(y[static_cast<std::size_t>(m)] == 0.0);  // past count: untouched
}

// `steps` steps of the method from the cloud, through the problem's path.
template <const auto& Tableau>
State advance(const DlpProblem& problem, DlpProblem::RhsPath path, const State& initial) {
  const_cast<DlpProblem&>(problem).set_rhs_path(path);
  ExplicitRungeKutta<Tableau> method("test");
  State state = initial;
  method.advance(problem, state, 0.0, 2e-4, 9);
  const_cast<DlpProblem&>(problem).set_rhs_path(DlpProblem::RhsPath::simd);
  return state;
}

template <const auto& Tableau>
void check_same_bits(const std::string& case_name, bool fused) {
  // 203 particles: three full blocks of 64 and a tail of 11.
  const test::PhysicsProblem p({Parameters{}, find_case(case_name).terms}, test::varied_cloud(203, 11));
  BOOST_TEST(static_cast<bool>(p.problem->fused_steps(&Tableau, 64)) == fused, case_name);
  const State y = p.problem->initial_state();
  const State with = advance<Tableau>(*p, DlpProblem::RhsPath::simd, y);
  const State without = advance<Tableau>(*p, DlpProblem::RhsPath::simd_unfused, y);
  BOOST_TEST((with == without).all(), case_name << ": fused and block steps differ");
  BOOST_TEST(!(with == y).all(), case_name << ": nothing moved");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(fused_runge_kutta)

BOOST_AUTO_TEST_CASE(each_tableau_multiplies_by_its_stability_polynomial) {
  for (int count : {64, 11}) {  // a full block (compile-time count) and a tail
    check_decay<tableau::euler>(count);
    check_decay<tableau::midpoint>(count);
    check_decay<tableau::heun>(count);
    check_decay<tableau::rk4>(count);
  }
}

// Cases without the C_D(Re) law or burning step fused; the others through the block kernels.
// Either way the bits are those of the block right-hand side's steps.
BOOST_AUTO_TEST_CASE(dlp_fused_steps_give_the_block_steps_bits) {
  for (const std::string name : {"similarity", "gravity", "drag", "drag-gravity", "drag-heat"}) {
    check_same_bits<tableau::euler>(name, true);
    check_same_bits<tableau::midpoint>(name, true);
    check_same_bits<tableau::heun>(name, true);
    check_same_bits<tableau::rk4>(name, true);
  }
  for (const std::string name : {"drag-law", "burn", "full"}) check_same_bits<tableau::midpoint>(name, false);
}

BOOST_AUTO_TEST_CASE(no_fused_steps_off_the_simd_path_or_for_other_tableaux) {
  const test::PhysicsProblem p({Parameters{}, find_case("drag").terms}, test::varied_cloud(10, 12));
  auto& problem = const_cast<DlpProblem&>(*p);
  static constexpr ButcherTableau<2> ralston{{{{0.0, 0.0}, {2.0 / 3.0, 0.0}}}, {0.25, 0.75}, {0.0, 2.0 / 3.0}, 2};
  BOOST_TEST(!problem.fused_steps(&ralston, 64));  // a tableau of the user's: the generic step
  BOOST_TEST(!problem.fused_steps(&tableau::midpoint, 32));
  problem.set_rhs_path(DlpProblem::RhsPath::simd_unfused);
  BOOST_TEST(!problem.fused_steps(&tableau::midpoint, 64));
  problem.set_rhs_path(DlpProblem::RhsPath::scalar);
  BOOST_TEST(!problem.fused_steps(&tableau::midpoint, 64));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_fused_runge_kutta
