// The perturbations of `dlpverify sharpness` (integrators/tableau/sharpness.hpp): every a_ij below
// the diagonal, every b_i and every c_i once, relative for a nonzero coefficient and absolute for a
// zero one, the others untouched.
#include <boost/test/unit_test.hpp>

#include "integrators/tableau/sharpness.hpp"

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
