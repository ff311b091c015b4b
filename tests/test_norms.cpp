// Error norms of docs/model.md §5 (seed eqs. 33–34) on a hand-made three-particle cloud.
#include <boost/test/unit_test.hpp>

#include "problems/dlp/problem.hpp"

#include <cmath>

#include "dlpverify/norms.hpp"
#include "problems/dlp/cloud.hpp"

namespace unit_norms {

using namespace dlpverify;
using namespace dlpverify::dlp;
namespace tt = boost::test_tools;

namespace {
// Reference positions (1, 0, 0), (0, 2, 0), (2, 0, 0) (Σ‖x‖² = 1 + 4 + 4 = 9); the numerical
// positions differ from them by (1, 2, 2), (0, 0, 0), (0, 3, 4) — lengths 3, 0, 5.
// Velocities differ only in particle 1, by (0, 0, −2); temperatures by (+4, −3, 0) around 300 K.
void make_pair(Cloud& numerical, Cloud& reference) {
  reference = Cloud(3);
  reference.set_particle(0, {1.0, 0.0, 0.0, 10.0, 0.0, 0.0, 300.0, 1e-9});
  reference.set_particle(1, {0.0, 2.0, 0.0, 0.0, 10.0, 0.0, 300.0, 1e-9});
  reference.set_particle(2, {2.0, 0.0, 0.0, 0.0, 0.0, 10.0, 300.0, 1e-9});
  numerical = reference;
  auto& s = numerical.state();
  s(0, X) += 1.0, s(0, Y) += 2.0, s(0, Z) += 2.0;
  s(2, Y) += 3.0, s(2, Z) += 4.0;
  s(1, VZ) -= 2.0;
  s(0, TEMPERATURE) += 4.0, s(1, TEMPERATURE) -= 3.0;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(norms)

// Position: |e| = √(9 + 0 + 25) = √34; rms = √(34/3); relative = √34 / √9 = √34 / 3; max = 5.
BOOST_AUTO_TEST_CASE(position_by_hand) {
  Cloud numerical, reference;
  make_pair(numerical, reference);
  const ErrorNorms n = error_norms(numerical.state(), reference.state(), {"position", X, 3, "m"});
  BOOST_TEST(n.l2 == std::sqrt(34.0), tt::tolerance(1e-15));
  BOOST_TEST(n.rms == std::sqrt(34.0 / 3.0), tt::tolerance(1e-15));
  BOOST_TEST(n.reference_l2 == 3.0, tt::tolerance(1e-15));
  BOOST_TEST(n.relative == std::sqrt(34.0) / 3.0, tt::tolerance(1e-15));
  BOOST_TEST(n.max == 5.0, tt::tolerance(1e-15));

  const Eigen::ArrayXd per_particle = member_errors(numerical.state(), reference.state(), {"position", X, 3, "m"});
  BOOST_REQUIRE(per_particle.size() == 3);
  BOOST_TEST(per_particle(0) == 3.0, tt::tolerance(1e-15));
  BOOST_TEST(per_particle(1) == 0.0);
  BOOST_TEST(per_particle(2) == 5.0, tt::tolerance(1e-15));
}

// Velocity: only particle 1 is off, by 2: |e| = 2, rms = 2/√3, relative = 2 / √(3 · 100), max = 2.
BOOST_AUTO_TEST_CASE(velocity_by_hand) {
  Cloud numerical, reference;
  make_pair(numerical, reference);
  const ErrorNorms n = error_norms(numerical.state(), reference.state(), {"velocity", VX, 3, "m/s"});
  BOOST_TEST(n.l2 == 2.0, tt::tolerance(1e-15));
  BOOST_TEST(n.rms == 2.0 / std::sqrt(3.0), tt::tolerance(1e-15));
  BOOST_TEST(n.relative == 2.0 / std::sqrt(300.0), tt::tolerance(1e-15));
  BOOST_TEST(n.max == 2.0, tt::tolerance(1e-15));
}

// A one-field group, temperature: |e| = √(16 + 9) = 5, rms = 5/√3, relative = 5 / √(3 · 300²),
// max = 4. Mass is untouched: every norm is zero.
BOOST_AUTO_TEST_CASE(scalar_groups_by_hand) {
  Cloud numerical, reference;
  make_pair(numerical, reference);
  const ErrorNorms t = error_norms(numerical.state(), reference.state(), {"temperature", TEMPERATURE, 1, "K"});
  BOOST_TEST(t.l2 == 5.0, tt::tolerance(1e-15));
  BOOST_TEST(t.rms == 5.0 / std::sqrt(3.0), tt::tolerance(1e-15));
  BOOST_TEST(t.relative == 5.0 / (300.0 * std::sqrt(3.0)), tt::tolerance(1e-15));
  BOOST_TEST(t.max == 4.0, tt::tolerance(1e-15));

  const ErrorNorms m = error_norms(numerical.state(), reference.state(), {"mass", MASS, 1, "kg"});
  BOOST_TEST(m.l2 == 0.0);
  BOOST_TEST(m.rms == 0.0);
  BOOST_TEST(m.relative == 0.0);
  BOOST_TEST(m.max == 0.0);
}

// docs/model.md §5: T and m are measured only when their equations are active.
BOOST_AUTO_TEST_CASE(measured_groups) {
  Lattice lattice;
  lattice.outer = 2;
  const DlpProblem drag(find_case("drag"), Parameters{}, lattice, Launch{});
  BOOST_TEST(drag.variables().size() == 2u);
  const DlpProblem burn(find_case("burn"), Parameters{}, lattice, Launch{});  // drag, heat and burning
  const auto groups = burn.variables();
  BOOST_REQUIRE(groups.size() == 4u);
  BOOST_TEST(groups[0].name == "position");
  BOOST_TEST(groups[1].first_field == VX);
  BOOST_TEST(groups[2].first_field == TEMPERATURE);
  BOOST_TEST(groups[3].first_field == MASS);
}

// Each member's error is correctly rounded, whatever vector lanes it falls in: for one field it is
// √((y − y_ref)²) as std::sqrt gives it member by member. Eigen's array sqrt with its
// default EIGEN_FAST_MATH is an approximation on AVX-512 (rsqrt14 and two Newton steps) that
// differs from it in the last bit for 44 % of such values; the build sets EIGEN_FAST_MATH=0.
BOOST_AUTO_TEST_CASE(member_errors_are_correctly_rounded) {
  const Eigen::Index n = 4099;  // not a multiple of any vector width
  State numerical(n, 1), reference(n, 1);
  for (Eigen::Index p = 0; p < n; ++p) {
    numerical(p, 0) = std::ldexp(1.0 + std::fmod(0.618033988749895 * static_cast<double>(p), 1.0), static_cast<int>(p % 41) - 20);
    reference(p, 0) = numerical(p, 0) * (1.0 - std::fmod(0.414213562373095 * static_cast<double>(p), 1.0));
  }
  const Eigen::ArrayXd errors = member_errors(numerical, reference, Variable{"y", 0, 1, "1"});
  long differ = 0;
  for (Eigen::Index p = 0; p < n; ++p) {
    const double d = numerical(p, 0) - reference(p, 0);
    differ += errors[p] != std::sqrt(d * d);
  }
  BOOST_TEST(differ == 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_norms
