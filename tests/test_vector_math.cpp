// The SIMD path (issue: speed): SLEEF's vector cbrt and pow against libm over the ranges the DLP
// cases reach, the block right-hand side against the scalar per-particle one, NaN still caught
// after vectorisation, and results independent of thread count and block size.
#include <boost/test/unit_test.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <omp.h>

#include "dlp_support.hpp"
#include "problems/dlp/block_rates.hpp"
#include "problems/dlp/case.hpp"
#include "simd/vector_math.hpp"

namespace unit_vector_math {

using namespace dlpverify;
using namespace dlpverify::dlp;

namespace {

// Units in the last place between two finite doubles of the same sign.
std::int64_t ulps(double a, double b) {
  const auto ia = std::bit_cast<std::int64_t>(a), ib = std::bit_cast<std::int64_t>(b);
  return ia > ib ? ia - ib : ib - ia;
}

// n values log-uniform in [lo, hi].
std::vector<double> log_uniform(double lo, double hi, int n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  std::vector<double> x(static_cast<std::size_t>(n));
  for (double& v : x) v = std::exp(u(random));
  return x;
}

// The largest error in ulp of SLEEF's pow, and of libm's, against long double powl rounded to double
// (x87's 64-bit mantissa: the correctly rounded result but for near-ties).
struct Worst {
  std::int64_t sleef = 0, libm = 0, apart = 0;  // apart: SLEEF against libm
};
Worst worst_pow(const std::vector<double>& x, double exponent) {
  std::vector<double> out(x.size());
  simd::pow(x.data(), exponent, out.data(), static_cast<int>(x.size()));
  Worst w;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double reference = static_cast<double>(std::pow(static_cast<long double>(x[i]), static_cast<long double>(exponent)));
    w.sleef = std::max(w.sleef, ulps(out[i], reference));
    w.libm = std::max(w.libm, ulps(std::pow(x[i], exponent), reference));
    w.apart = std::max(w.apart, ulps(out[i], std::pow(x[i], exponent)));
  }
  return w;
}


State block_rhs(const DlpProblem& problem, const State& y, DlpProblem::RhsPath path, int first, int count) {
  const_cast<DlpProblem&>(problem).set_rhs_path(path);
  State dydt(count, kFields);
  State block = y.middleRows(first, count);
  std::vector<const double*> in(kFields);
  std::vector<double*> out(kFields);
  for (int f = 0; f < kFields; ++f) {
    in[f] = block.col(f).data();
    out[f] = dydt.col(f).data();
  }
  problem.rhs(0.0, first, count, in.data(), out.data());
  const_cast<DlpProblem&>(problem).set_rhs_path(DlpProblem::RhsPath::simd);
  return dydt;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(vector_math)

// SLEEF's u10 functions promise 1 ulp; measured here against long double, and against libm.
// glibc's cbrt is the less accurate of the two: up to 2.6 ulp from the true root on these
// arguments (e.g. ∛0x1.8f12793b8a724p-54: libm −2.60 ulp, SLEEF +0.40 ulp, by a 60-digit Newton
// iteration), so SLEEF and libm may differ by 3 ulp there while SLEEF stays within 1.
BOOST_AUTO_TEST_CASE(sleef_within_1_ulp_and_near_libm_over_the_cases_ranges) {
  BOOST_TEST_MESSAGE("vector ISA: " << simd::isa() << ", " << simd::lanes() << " lanes");
  const Parameters p;
  const double from_mass = 6.0 / (std::numbers::pi * p.rho_particle);
  // d = ∛(6m/(πρ_p)) for m from m0 down to a thousandth of it (burning stops before that).
  const std::vector<double> cbrt_args = log_uniform(from_mass * p.mass0() * 1e-3, from_mass * p.mass0(), 100000, 1);
  std::vector<double> roots(cbrt_args.size());
  simd::cbrt(cbrt_args.data(), roots.data(), static_cast<int>(roots.size()));
  Worst cbrt;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const double reference = static_cast<double>(std::cbrt(static_cast<long double>(cbrt_args[i])));
    cbrt.sleef = std::max(cbrt.sleef, ulps(roots[i], reference));
    cbrt.apart = std::max(cbrt.apart, ulps(roots[i], std::cbrt(cbrt_args[i])));
  }
  BOOST_TEST(cbrt.sleef <= 1);
  BOOST_TEST(cbrt.apart <= 3);
  // The C_D(Re) law's Re^−0.85, Re = ρ_a ‖w‖ d / μ_a for ‖w‖ from 1e-8 m/s to 1 km/s and d from
  // 1 µm to 1 mm: 7e-10 … 7e4.
  const Worst law = worst_pow(log_uniform(1e-10, 1e5, 100000, 2), -0.85);
  BOOST_TEST(law.sleef <= 1);
  BOOST_TEST(law.apart <= 2);
  BOOST_TEST_MESSAGE("Re^-0.85: SLEEF " << law.sleef << " ulp, libm " << law.libm << " ulp, apart " << law.apart);
  // At rest the power is taken of the smallest normal double (rate_terms::law_reynolds), not of
  // Re = 0, whose power is +∞: finite, so 28 Re^−0.85 ‖w‖ is 0 there (below).
  double smallest = std::numeric_limits<double>::min(), out = 0.0;
  simd::pow(&smallest, -0.85, &out, 1);
  BOOST_TEST(std::isfinite(out));
  BOOST_TEST(ulps(out, std::pow(smallest, -0.85)) <= 2);
}

// C_D(Re)‖w‖ = 0.48‖w‖ + 28 Re^−0.85 ‖w‖ → 0 as ‖w‖ → 0: a particle at rest has no drag, on both
// paths, and one barely moving has a finite one.
BOOST_AUTO_TEST_CASE(the_law_s_drag_vanishes_at_rest) {
  Cloud cloud(2);
  cloud.set_particle(0, {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1000.0, Parameters{}.mass0()});
  cloud.set_particle(1, {0.0, 0.0, 0.0, 1e-100, 0.0, 0.0, 1000.0, Parameters{}.mass0()});
  const test::PhysicsProblem p({Parameters{}, find_case("full").terms}, cloud);
  const State y = p.problem->initial_state();
  for (auto path : {DlpProblem::RhsPath::simd, DlpProblem::RhsPath::scalar}) {
    const State dydt = block_rhs(*p, y, path, 0, 2);
    BOOST_TEST(dydt(0, VX) == 0.0);
    BOOST_TEST(dydt(0, VZ) == -Parameters{}.gravity);  // gravity alone
    BOOST_TEST(dydt.isFinite().all());
    BOOST_TEST(dydt(1, VX) < 0.0);  // opposes the motion
  }
}

BOOST_AUTO_TEST_CASE(a_value_does_not_depend_on_where_it_sits) {
  const std::vector<double> x = log_uniform(1e-3, 1e3, 67, 4);
  std::vector<double> all(67), tail(3);
  simd::pow(x.data(), 0.15, all.data(), 67);          // x[64..66] in the padded tail
  simd::pow(x.data() + 64, 0.15, tail.data(), 3);     // the same values alone
  for (int i = 0; i < 3; ++i) BOOST_TEST(std::bit_cast<std::uint64_t>(all[64 + i]) == std::bit_cast<std::uint64_t>(tail[i]));
}

BOOST_AUTO_TEST_CASE(block_rates_equal_the_scalar_rates) {
  const Cloud cloud = test::varied_cloud(203, 5);
  for (const Case& c : all_cases()) {
    const test::PhysicsProblem p({Parameters{}, c.terms}, cloud);
    const State y = p.problem->initial_state();
    const State simd = block_rhs(*p, y, DlpProblem::RhsPath::simd, 0, 203);
    const State scalar = block_rhs(*p, y, DlpProblem::RhsPath::scalar, 0, 203);
    const bool uses_pow = c.terms.burning || (c.terms.drag && c.terms.drag_law == DragLaw::reynolds);
    double worst = 0.0;
    for (Eigen::Index i = 0; i < simd.size(); ++i)
      if (simd(i) != scalar(i)) worst = std::max(worst, std::abs(simd(i) - scalar(i)) / std::abs(scalar(i)));
    // Without pow or cbrt the same formulas in the same order give the same bits; with them,
    // SLEEF's and libm's results (up to 3 ulp apart, above) carry through a few operations.
    BOOST_TEST(worst <= (uses_pow ? 1e-14 : 0.0), c.name << ": largest relative difference " << worst);
  }
}

BOOST_AUTO_TEST_CASE(results_do_not_depend_on_block_size_or_thread_count) {
  const Cloud cloud = test::varied_cloud(300, 6);
  const Case& full = find_case("full");
  const test::PhysicsProblem p({Parameters{}, full.terms}, cloud);
  const State y = p.problem->initial_state();
  // Particles 100 … 136 alone, and inside a block of 300: the same bits.
  const State alone = block_rhs(*p, y, DlpProblem::RhsPath::simd, 100, 37);
  const State inside = block_rhs(*p, y, DlpProblem::RhsPath::simd, 0, 300);
  BOOST_TEST((alone == inside.middleRows(100, 37)).all());
  // RK2 over 20 steps on 1 and on 2 threads: the same bits.
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  State one = y, two = y;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  rk2.advance(*p, one, 0.0, 1e-4, 20);
  omp_set_num_threads(2);
  rk2.advance(*p, two, 0.0, 1e-4, 20);
  omp_set_num_threads(threads);
  BOOST_TEST((one == two).all());
}

BOOST_AUTO_TEST_CASE(a_nan_in_the_state_survives_vectorisation) {
  const Cloud cloud = test::varied_cloud(64, 7);
  const test::PhysicsProblem p({Parameters{}, find_case("full").terms}, cloud);
  State clean = p.problem->initial_state(), poisoned = clean;
  poisoned(17, VX) = std::numeric_limits<double>::quiet_NaN();
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  rk2.advance(*p, clean, 0.0, 1e-4, 5);
  rk2.advance(*p, poisoned, 0.0, 1e-4, 5);
  // The poisoned particle is not finite (isfinite still tells), and no other particle is touched.
  BOOST_TEST(!std::isfinite(poisoned(17, VX)));
  BOOST_TEST(!poisoned.row(17).isFinite().all());
  for (Eigen::Index i = 0; i < clean.rows(); ++i)
    if (i != 17) BOOST_TEST((poisoned.row(i) == clean.row(i)).all());
}

// Inert fields (T and m without heat and burning) are carried, not staged: the same bits as
// staging them with their zero rates, through a wrapper that declares no field inert.
BOOST_AUTO_TEST_CASE(inert_fields_are_carried_unchanged_with_the_same_bits) {
  const test::PhysicsProblem p({Parameters{}, find_case("drag").terms}, test::varied_cloud(100, 8));
  const std::vector<bool> inert = p.problem->inert_fields();
  BOOST_TEST((inert[TEMPERATURE] && inert[MASS] && !inert[VX]));
  const test::WithoutKinks plain(*p);  // forwards the rhs; declares no field inert
  BOOST_TEST(inert_fields(plain)[TEMPERATURE] == false);
  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  State carried = p.problem->initial_state(), staged = carried;
  rk4.advance(*p, carried, 0.0, 1e-4, 7);
  rk4.advance(plain, staged, 0.0, 1e-4, 7);
  BOOST_TEST((carried == staged).all());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_vector_math
