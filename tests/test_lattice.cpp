// The lattice cloud of docs/model.md §2: exact particle counts, the launch state, and the kinetic energy.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "problems/dlp/cloud.hpp"
#include "problems/dlp/kinetic_energy.hpp"
#include "problems/dlp/parameters.hpp"

namespace unit_lattice {

using namespace dlpverify;
using namespace dlpverify::dlp;

namespace {
Lattice make_lattice(Shape shape, int outer) {
  Lattice l;
  l.shape = shape;
  l.outer = outer;
  l.inner = Lattice::default_inner(shape, outer);
  return l;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(lattice)

// A rank's share under mpirun builds its members alone (docs/mpi.md): any range of points is the
// whole cloud's rows, bit for bit — from the start, across planes, to past the end, and empty.
BOOST_AUTO_TEST_CASE(members_alone_are_the_clouds_rows) {
  const Launch launch{100.0};
  for (const Shape shape : {Shape::sphere, Shape::shell}) {
    const Lattice lattice = make_lattice(shape, 10);
    const Cloud whole = make_cloud(lattice, launch, Parameters{});
    const Eigen::Index n = whole.size();
    for (const auto& [first, count] : std::vector<std::pair<Eigen::Index, Eigen::Index>>{
             {0, n}, {0, 1}, {5, 17}, {1000, 2500}, {n - 3, 10}, {n, 4}, {7, 0}}) {
      const Cloud part = make_cloud_members(lattice, launch, Parameters{}, first, count);
      const Eigen::Index rows = std::max<Eigen::Index>(0, std::min(first + count, n) - first);
      BOOST_TEST_REQUIRE(part.size() == rows, "points " << first << " + " << count);
      BOOST_TEST((part.state() == whole.state().middleRows(first, rows)).all(), "points " << first << " + " << count);
    }
  }
}

// docs/model.md §2: "R_out = 10: S has 4,168 particles, SS 3,684"; "R_out = 100 … 4,187,856 particles"
// (sphere) and 597,624 (shell).
BOOST_AUTO_TEST_CASE(counts_of_spec_2) {
  BOOST_TEST(count_lattice_points(make_lattice(Shape::sphere, 10)) == 4168);
  BOOST_TEST(count_lattice_points(make_lattice(Shape::shell, 10)) == 3684);
  BOOST_TEST(count_lattice_points(make_lattice(Shape::sphere, 100)) == 4187856);
  BOOST_TEST(count_lattice_points(make_lattice(Shape::shell, 100)) == 597624);
}

// The count works column by column (for the memory estimate before a cloud exists); it must be
// the number of points inner² ≤ i² + j² + k² ≤ outer² an enumeration finds, for every radius pair.
BOOST_AUTO_TEST_CASE(count_matches_enumeration) {
  for (const bool axis : {false, true})
    for (int outer = 0; outer <= 12; ++outer)
      for (int inner = 0; inner <= outer + 1; ++inner) {
        long long enumerated = 0;
        const int plane = axis ? 0 : outer;
        for (long long i = -plane; i <= plane; ++i)
          for (long long j = -plane; j <= plane; ++j)
            for (long long k = -outer; k <= outer; ++k) {
              const long long r2 = i * i + j * j + k * k;
              enumerated += r2 >= static_cast<long long>(inner) * inner && r2 <= static_cast<long long>(outer) * outer;
            }
        Lattice l;
        l.outer = outer;
        l.inner = inner;
        l.z_axis_only = axis;
        BOOST_TEST(count_lattice_points(l) == enumerated, "outer " << outer << " inner " << inner << " axis " << axis);
      }
}

// docs/model.md §2: sphere 1 ≤ r ≤ R_out, shell R_out − 5 ≤ r ≤ R_out.
BOOST_AUTO_TEST_CASE(default_inner_radius) {
  BOOST_TEST(Lattice::default_inner(Shape::sphere, 100) == 1);
  BOOST_TEST(Lattice::default_inner(Shape::shell, 100) == 95);
  BOOST_TEST(Lattice::default_inner(Shape::shell, 10) == 5);
}

// docs/model.md §2 launch state at R_out = 10 with the defaults of docs/model.md §8 (Δ = d0 = 1e-4 m, u_s = 100 m/s).
BOOST_AUTO_TEST_CASE(launch_state_r10) {
  const Lattice l = make_lattice(Shape::sphere, 10);
  const Launch launch;
  const Parameters parameters;
  const Cloud cloud = make_cloud(l, launch, parameters);
  BOOST_REQUIRE(cloud.size() == 4168);

  // t0 = R_out Δ / u_s = 10 · 1e-4 / 100 = 1e-5 s (by hand).
  const double t0 = initial_time(l, launch);
  BOOST_TEST(t0 == 1e-5, boost::test_tools::tolerance(1e-15));
  // m0 = π ρ_p d0³ / 6 = π · 2700 · 1e-12 / 6 = 1.4137166941154069e-9 kg (by hand).
  const double m0 = parameters.mass0();
  BOOST_TEST(m0 == 1.4137166941154069e-9, boost::test_tools::tolerance(1e-14));

  const auto& s = cloud.state();
  const double spacing = l.spacing;
  for (Eigen::Index p = 0; p < cloud.size(); ++p) {
    // Every position is a lattice point (i, j, k)·Δ with 1 ≤ i² + j² + k² ≤ 100.
    long long r2 = 0;
    for (int f = X; f <= Z; ++f) {
      const double index = s(p, f) / spacing;
      const double rounded = std::round(index);
      BOOST_TEST_REQUIRE(std::abs(index - rounded) < 1e-12);
      BOOST_TEST_REQUIRE(s(p, f) == rounded * spacing);  // the lattice point itself, i·Δ
      r2 += static_cast<long long>(rounded) * static_cast<long long>(rounded);
    }
    BOOST_TEST_REQUIRE(r2 >= 1);
    BOOST_TEST_REQUIRE(r2 <= 100);
    // v0 = ξ u_s î = x0 / t0.
    for (int f = 0; f < 3; ++f)
      BOOST_TEST_REQUIRE(s(p, VX + f) == s(p, X + f) / t0, boost::test_tools::tolerance(1e-14));
    BOOST_TEST_REQUIRE(s(p, TEMPERATURE) == 1500.0);  // T_p0 (docs/model.md §8)
    BOOST_TEST_REQUIRE(s(p, MASS) == m0);
  }

  // Lexicographic (i, j, k) order: the first particle is (−10, 0, 0)·Δ, the last (10, 0, 0)·Δ.
  BOOST_TEST(s(0, X) == -10 * spacing);
  BOOST_TEST(s(0, Y) == 0.0);
  BOOST_TEST(s(0, Z) == 0.0);
  BOOST_TEST(s(cloud.size() - 1, X) == 10 * spacing);

  // The outermost particle has ξ = 1 and speed u_s = 100 m/s, along −î.
  const Eigen::ArrayXd xi = similarity_coordinate(cloud, t0, launch);
  BOOST_TEST(xi(0) == 1.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(xi.maxCoeff() == 1.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(s(0, VX) == -100.0, boost::test_tools::tolerance(1e-14));
  const double speed = std::sqrt(s(0, VX) * s(0, VX) + s(0, VY) * s(0, VY) + s(0, VZ) * s(0, VZ));
  BOOST_TEST(speed == 100.0, boost::test_tools::tolerance(1e-14));
  // The innermost particles (r = 1) have ξ = 1/10.
  BOOST_TEST(xi.minCoeff() == 0.1, boost::test_tools::tolerance(1e-14));
}

// The shell at R_out = 10 holds 5 ≤ r ≤ 10, so ξ ∈ [0.5, 1].
BOOST_AUTO_TEST_CASE(shell_r10) {
  const Lattice l = make_lattice(Shape::shell, 10);
  const Launch launch;
  const Cloud cloud = make_cloud(l, launch, Parameters{});
  BOOST_REQUIRE(cloud.size() == 3684);
  const Eigen::ArrayXd xi = similarity_coordinate(cloud, initial_time(l, launch), launch);
  BOOST_TEST(xi.minCoeff() == 0.5, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(xi.maxCoeff() == 1.0, boost::test_tools::tolerance(1e-14));
}

// docs/model.md §2: KE / (0.3 N m u_s²) = Σξ² / (0.6 N) = 0.997337 at R_out = 10 and 0.999627 at 50
// (six digits; the exact values are 0.99733685… and 0.99962663…, Σ r² / (R_out² · 0.6 N) by hand).
BOOST_AUTO_TEST_CASE(kinetic_energy_ratio) {
  const Launch launch;
  const Parameters parameters;
  for (const auto& [outer, expected] : {std::pair{10, 0.997337}, std::pair{50, 0.999627}}) {
    BOOST_TEST_CONTEXT("R_out = " << outer) {
      const Lattice l = make_lattice(Shape::sphere, outer);
      const Cloud cloud = make_cloud(l, launch, parameters);
      const double n = static_cast<double>(cloud.size());
      const double t0 = initial_time(l, launch);
      const Eigen::ArrayXd xi = similarity_coordinate(cloud, t0, launch);
      const double ratio_xi = xi.square().sum() / (0.6 * n);
      const auto& s = cloud.state();
      const double u_s = launch.expansion_speed;
      const double kinetic = 0.5 * (s.col(MASS) * (s.col(VX).square() + s.col(VY).square() + s.col(VZ).square())).sum();
      const double ratio_ke = kinetic / (0.3 * n * parameters.mass0() * u_s * u_s);
      BOOST_TEST(ratio_ke == ratio_xi, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(std::abs(ratio_xi - expected) <= 5e-7);  // six decimal places
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

// docs/model.md §2: the lattice cloud's kinetic energy against the continuous sphere's 0.3 M u_s², through
// the model's own kinetic_energy (Σ ½ m v²), to the 6 digits docs/model.md §2 gives.
BOOST_AUTO_TEST_SUITE(kinetic_energy_ratio)

double ratio_at(int outer) {
  const dlpverify::dlp::Launch launch{100.0};
  const dlpverify::dlp::Cloud cloud =
      dlpverify::dlp::make_cloud(dlpverify::dlp::Lattice{dlpverify::dlp::Shape::sphere, outer, 1, 1e-4}, launch, dlpverify::dlp::Parameters{});
  return dlpverify::dlp::similarity_energy_ratio(cloud, launch);
}

BOOST_AUTO_TEST_CASE(r_out_10) { BOOST_TEST(ratio_at(10) == 0.997337, boost::test_tools::tolerance(0.5e-6 / 0.997337)); }
BOOST_AUTO_TEST_CASE(r_out_50) { BOOST_TEST(ratio_at(50) == 0.999627, boost::test_tools::tolerance(0.5e-6 / 0.999627)); }
BOOST_AUTO_TEST_CASE(r_out_100) { BOOST_TEST(ratio_at(100) == 0.999852, boost::test_tools::tolerance(0.5e-6 / 0.999852)); }

// KE = Σ ½ m v² by hand for two particles.
BOOST_AUTO_TEST_CASE(hand_sum) {
  dlpverify::dlp::Cloud cloud(2);
  cloud.state().setZero();
  cloud.state()(0, dlpverify::dlp::VX) = 3.0;
  cloud.state()(0, dlpverify::dlp::VY) = 4.0;  // ‖v‖ = 5
  cloud.state()(0, dlpverify::dlp::MASS) = 2.0;
  cloud.state()(1, dlpverify::dlp::VZ) = -1.0;
  cloud.state()(1, dlpverify::dlp::MASS) = 0.5;
  BOOST_TEST(dlpverify::dlp::kinetic_energy(cloud) == 0.5 * 2.0 * 25.0 + 0.5 * 0.5 * 1.0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_lattice
