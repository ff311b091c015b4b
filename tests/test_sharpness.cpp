// The perturbations of `dlpverify sharpness` (integrators/tableau/sharpness.hpp): every a_ij below
// the diagonal, every b_i and every c_i once, relative for a nonzero coefficient and absolute for a
// zero one, the others untouched; and a mutant's error constant judged in the unperturbed one's band.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "dlpverify/integrator.hpp"
#include "dlpverify/study.hpp"
#include "integrators/tableau/sharpness.hpp"

namespace unit_sharpness {

using namespace dlpverify;

BOOST_AUTO_TEST_SUITE(sharpness_mutations)

BOOST_AUTO_TEST_CASE(midpoint_has_five) {
  const RuntimeTableau midpoint = parse_tableau(
      "name = \"midpoint\"\norder = 2\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "midpoint.toml");
  const std::vector<TableauMutation> m = tableau_mutations(midpoint, 0.01);
  BOOST_REQUIRE(m.size() == 5u);
  const std::vector<std::string> names{"a_21", "b_1", "b_2", "c_1", "c_2"};
  const std::vector<double> perturbed{0.505, 0.01, 1.01, 0.01, 0.505};  // x (1 + δ), or δ for a zero
  for (std::size_t i = 0; i < m.size(); ++i) {
    BOOST_TEST(m[i].coefficient == names[i]);
    BOOST_TEST(m[i].perturbed == perturbed[i]);
    BOOST_TEST(m[i].absolute == (m[i].original == 0.0));
  }
  BOOST_TEST(m[0].tableau.a[1][0] == 0.505);
  BOOST_TEST(m[0].tableau.c[1] == 0.5);  // only a_21 moved
  BOOST_TEST(m[4].tableau.c[1] == 0.505);
  BOOST_TEST(m[4].tableau.a[1][0] == 0.5);
  BOOST_TEST(m[1].tableau.b[0] == 0.01);
  BOOST_TEST(m[1].tableau.b[1] == 1.0);
}

// s stages: s(s − 1)/2 coefficients below the diagonal, s weights, s nodes: 14 for RK4.
BOOST_AUTO_TEST_CASE(rk4_has_fourteen) {
  RuntimeTableau rk4;
  rk4.order = 4;
  rk4.c = {0.0, 0.5, 0.5, 1.0};
  rk4.b = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  rk4.a = {{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}};
  const std::vector<TableauMutation> m = tableau_mutations(rk4, 0.02);
  BOOST_REQUIRE(m.size() == 14u);
  BOOST_TEST(m[1].coefficient == "a_31");
  BOOST_TEST(m[1].perturbed == 0.02);  // a zero below the diagonal moves to δ
  BOOST_TEST(m[5].coefficient == "a_43");
  BOOST_TEST(m[5].perturbed == 1.02);
}

BOOST_AUTO_TEST_SUITE_END()

// A mutant's error constant is judged against the unperturbed one's band,
// |C − C_base| ≤ tol C_base (docs/verification.md, "How sharp is the check"), and its ratio is
// C / C_base. The band is the unperturbed constant's, so it is not symmetric in the ratio: at
// tol = 5% a mutant 5.1% above leaves it (0.051 > 0.05) and one 4.9% below stays in it
// (0.049 ≤ 0.05), where the roles swapped would say the opposite (0.051 ≤ 0.05 × 1.051 = 0.05255,
// 0.049 > 0.05 × 0.951 = 0.04755). The studies are states with an error of exactly s C Δt²: the
// unperturbed tableau's at s = 1, every mutant's at s = `scale`, so every ratio is `scale`.
namespace {

constexpr int kLevels = 4;

// t_end = 1, Δt_k = 0.1 / 2^k; one field x of four members, y_k = y + s (p + 1) Δt_k².
StudyResult scaled_error_study(double scale) {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.ratio = 2.0;
  plan.levels = kLevels;
  plan.expected_order = 2.0;
  plan.variables = {{"x", 0, 1, "m"}};
  State exact(4, 1);
  exact << 1.0, -2.0, 3.0, 0.5;
  std::vector<State> states;
  for (int k = 0; k < kLevels; ++k) {
    const double dt = 0.1 / std::pow(2.0, k);
    State y = exact;
    for (int p = 0; p < 4; ++p) y(p, 0) += scale * (p + 1) * dt * dt;
    states.push_back(y);
  }
  return analyse_states(plan, states, &exact, {0.0});
}

// The midpoint rule's five mutants judged with every mutant's constant `scale` times the unperturbed.
SharpnessReport judged_at(double scale) {
  const RuntimeTableau midpoint = parse_tableau(
      "name = \"midpoint\"\norder = 2\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "midpoint.toml");
  const IntegratorStudy study = [scale](Integrator& integrator) {
    const bool mutant = integrator.name().find(" with ") != std::string::npos;  // "… with a_21 = 0.505"
    return scaled_error_study(mutant ? scale : 1.0);
  };
  return measure_sharpness(midpoint, SharpnessSettings{0.01, 0.1, 0.05}, study, IntegratorStudy{});
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sharpness_constant_band)

BOOST_AUTO_TEST_CASE(a_constant_5_1_percent_above_leaves_the_band) {
  const SharpnessReport r = judged_at(1.051);
  BOOST_REQUIRE(r.mutations.size() == 5u);
  for (const MutationVerdict& m : r.mutations) {
    BOOST_TEST_CONTEXT(m.mutation.coefficient) {
      BOOST_TEST(!m.study.order);  // order 2 exactly: only the constant can catch it
      BOOST_REQUIRE(m.study.constant_ratio.size() == 1u);
      BOOST_TEST(m.study.constant_ratio[0] == 1.051, boost::test_tools::tolerance(1e-9));  // C / C_base
      BOOST_TEST(m.study.constant);  // |1.051 − 1| = 0.051 > 0.05
    }
  }
  BOOST_TEST(r.caught_by_study() == 5);
}

BOOST_AUTO_TEST_CASE(a_constant_4_9_percent_below_stays_in_it) {
  const SharpnessReport r = judged_at(0.951);
  BOOST_REQUIRE(r.mutations.size() == 5u);
  for (const MutationVerdict& m : r.mutations) {
    BOOST_TEST_CONTEXT(m.mutation.coefficient) {
      BOOST_REQUIRE(m.study.constant_ratio.size() == 1u);
      BOOST_TEST(m.study.constant_ratio[0] == 0.951, boost::test_tools::tolerance(1e-9));
      BOOST_TEST(!m.study.constant);  // |0.951 − 1| = 0.049 ≤ 0.05
    }
  }
  BOOST_TEST(r.caught_by_study() == 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_sharpness
