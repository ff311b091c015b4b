// The event-driven hard-sphere engine of docs/model.md §7.2 (src/events):
//   - a head-on collision worked out by hand: its time from the quadratic, the outgoing
//     velocities of unequal masses from momentum and energy conservation;
//   - the stable root against a long-double evaluation of the textbook root, near contact;
//   - a wall moving at u reflects v' = 2u − v, at the time the gap closes;
//   - with the walls at rest, kinetic energy is conserved to round-off over 10⁶ events (N = 108,
//     packing fraction 0.26), and so is the total energy of perfectly rough elastic spheres;
//   - the full collision model (restitution, sticking and sliding friction, spin) by hand;
//   - no pair ever overlaps with the overlap check after every event (walls at rest and moving),
//     and overlapping spheres are refused.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "compress/compression.hpp"
#include "compress/event_rate.hpp"
#include "compress/gas_setup.hpp"
#include "dlpverify/errors.hpp"
#include "events/engine.hpp"
#include "events/event_times.hpp"

using namespace dlpverify;
using namespace dlpverify::events;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

Box big_box() { return compress::cube(100.0); }

}  // namespace

BOOST_AUTO_TEST_SUITE(events)

// r = (−4, 0, 0), v = (2, 0, 0), σ = 1: b = −8, v² = 4, c = 15, √(b² − v²c) = 2, t = 15/(8 + 2) = 1.5.
BOOST_AUTO_TEST_CASE(head_on_pair_time_by_hand) {
  BOOST_TEST(pair_time(-4, 0, 0, 2, 0, 0, 1.0) == 1.5);
  BOOST_TEST(pair_time(4, 0, 0, 2, 0, 0, 1.0) == kNever);   // receding
  BOOST_TEST(pair_time(-4, 2, 0, 2, 0, 0, 1.0) == kNever);  // misses: impact parameter 2 > σ
  BOOST_TEST(pair_time(-0.999, 0, 0, 1, 0, 0, 1.0) == 0.0); // overlapping by round-off, approaching: now
}

// Masses 1 and 3, v_a = 2, v_b = 0 along x: momentum 2 and energy 2 give v_a' = (m_a − m_b)/(m_a + m_b) v_a = −1,
// v_b' = 2 m_a/(m_a + m_b) v_a = 1. Radii 0.5 and 0.25, centres 3 m apart: contact after (3 − 0.75)/2 = 1.125 s.
BOOST_AUTO_TEST_CASE(head_on_collision_by_hand) {
  Spheres s;
  s.add({-1.5, 0, 0}, {2, 0, 0}, 0.5, 1.0);
  s.add({1.5, 0, 0}, {0, 0, 0}, 0.25, 3.0);
  EventEngine engine(s, big_box());
  engine.run_until(1.125 - 1e-9);
  BOOST_TEST(engine.counts().pair == 0);
  engine.run_until(2.125);  // one second after contact
  BOOST_TEST(engine.counts().pair == 1);
  const Spheres& out = engine.spheres();
  BOOST_TEST(out.vx[0] == -1.0, boost::test_tools::tolerance(4 * kEps));
  BOOST_TEST(out.vx[1] == 1.0, boost::test_tools::tolerance(4 * kEps));
  BOOST_TEST(out.x[0] == 0.75 - 1.0, boost::test_tools::tolerance(8 * kEps));  // contact at x_a = 0.75
  BOOST_TEST(out.x[1] == 1.5 + 1.0, boost::test_tools::tolerance(8 * kEps));
}

// Nearly in contact (gap 1e-6 σ), approaching obliquely: the earlier root in the stable form
// c / (−b + √(b² − v²c)) against the textbook (−b − √(b² − v²c))/v² in long double from the same
// inputs. The tolerance is c's own cancellation, ε r²/c ≈ 1e-10.
BOOST_AUTO_TEST_CASE(near_contact_pair_time) {
  const double sigma = 0.04, d = sigma * (1.0 + 1e-6);
  const double r[3] = {-d * 0.6, -d * 0.8, 0.0}, v[3] = {9.0, 3.0, -1.0};
  long double b = 0, v2 = 0, rr = 0;
  for (int k = 0; k < 3; ++k) b += static_cast<long double>(r[k]) * v[k], v2 += static_cast<long double>(v[k]) * v[k],
                              rr += static_cast<long double>(r[k]) * r[k];
  const long double c = rr - static_cast<long double>(sigma) * sigma;
  const long double exact = (-b - std::sqrt(b * b - v2 * c)) / v2;
  BOOST_TEST(exact > 0.0L);
  BOOST_TEST(pair_time(r[0], r[1], r[2], v[0], v[1], v[2], sigma) == static_cast<double>(exact),
             boost::test_tools::tolerance(1e-9));
}

// Upper x wall at 2 moving at u = −0.5, sphere (R 0.5) at 0 with v_x = 3: the gap 1.5 closes at
// 3.5 m/s → contact at t = 3/7; then v_x' = 2u − v = −4.
BOOST_AUTO_TEST_CASE(moving_wall_reflects_two_u_minus_v) {
  BOOST_TEST(wall_time(1.5, 3.5) == 1.5 / 3.5);
  BOOST_TEST(wall_time(1.5, -0.1) == kNever);
  Spheres s;
  s.add({0, 0, 0}, {3, 0, 0}, 0.5, 1.0);
  Box box = compress::cube(4.0);
  EventEngine engine(s, box);
  engine.set_wall_speeds({0, 0, 0}, {-0.5, 0, 0});
  engine.run_until(3.0 / 7.0 + 1e-12);
  BOOST_TEST(engine.counts().wall == 1);
  BOOST_TEST(engine.spheres().vx[0] == -4.0);
  BOOST_TEST(engine.box().upper[0] == 2.0 - 0.5 * (3.0 / 7.0 + 1e-12), boost::test_tools::tolerance(4 * kEps));
}

// Walls at rest reflect exactly (v' = −v) and elastic pair collisions conserve energy up to one
// rounding each: over 10⁶ events the drift must stay under 10⁶ ε (it is ~1e-12, i.e. a random walk).
BOOST_AUTO_TEST_CASE(energy_conserved_over_a_million_events) {
  const compress::EventRate r = compress::measure_event_rate(108, 1000000, 10000, 3);
  BOOST_TEST(r.events == 1000000);
  BOOST_TEST(r.pair_events > 500000);  // a dense gas: mostly pair collisions
  BOOST_TEST(std::fabs(r.energy_drift) < 1e6 * kEps);
}

// Perfectly rough elastic spheres (e = 1, β0 = 1, sticking always: μ large) conserve translational
// plus rotational energy; the split between them changes.
BOOST_AUTO_TEST_CASE(rough_elastic_spheres_conserve_total_energy) {
  compress::GasSetup gas;
  gas.spheres = 64, gas.radius = 0.5, gas.edge = 8.0, gas.lattice = true, gas.speed_max = 1.0;
  EventEngine engine(compress::place_gas(gas, 5), compress::cube(gas.edge), {1.0, 1.0, 1e6});
  const double e0 = engine.kinetic_energy() + engine.rotational_energy();
  engine.run_events(100000);
  BOOST_TEST(engine.rotational_energy() > 0.05 * e0);
  BOOST_TEST(engine.kinetic_energy() + engine.rotational_energy() == e0, boost::test_tools::tolerance(1e5 * kEps));
}

// The full model by hand: equal spheres m = 1, R = 1, n = (1, 0, 0), v_a = (−1, 1, 0), v_b = 0, no
// spin. v_ab,c = (−1, 1, 0): J_n = −(1 + e)(−1)/B2 = 1 (e = 1, B2 = 2), t = (0, 1, 0), B1 = 7.
// Sticking (β0 = 1, μ large): J_t = −(1 + β0)·1/7 = −2/7, so v_a' = (0, 5/7, 0), v_b' = (−1, 2/7, 0),
// and n × J = (0, 0, −2/7) gives Δω = −R (n × J)/I = (0, 0, 5/7) for both (I = 2/5); the contact's
// tangential velocity is then reversed, (1, −1, 0). Sliding (μ = 0.1 < 2/7): J_t = −μ J_n = −0.1.
BOOST_AUTO_TEST_CASE(rough_collision_by_hand) {
  const double n[3] = {1, 0, 0};
  SphereKinematics a{{-1, 1, 0}, {0, 0, 0}, 1.0, 1.0}, b{{0, 0, 0}, {0, 0, 0}, 1.0, 1.0};
  collide({1.0, 1.0, 1e6}, n, a, b);
  const auto close = boost::test_tools::tolerance(4 * kEps);
  BOOST_TEST(a.v[0] == 0.0);
  BOOST_TEST(a.v[1] == 5.0 / 7.0, close);
  BOOST_TEST(b.v[0] == -1.0);
  BOOST_TEST(b.v[1] == 2.0 / 7.0, close);
  BOOST_TEST(a.w[2] == 5.0 / 7.0, close);
  BOOST_TEST(b.w[2] == 5.0 / 7.0, close);
  SphereKinematics c{{-1, 1, 0}, {0, 0, 0}, 1.0, 1.0}, d{{0, 0, 0}, {0, 0, 0}, 1.0, 1.0};
  collide({1.0, 1.0, 0.1}, n, c, d);
  BOOST_TEST(c.v[1] == 0.9, close);
  BOOST_TEST(d.v[1] == 0.1, close);
  SphereKinematics e{{-1, 1, 0}, {0, 0, 0}, 1.0, 1.0}, f{{0, 0, 0}, {0, 0, 0}, 1.0, 1.0};
  collide({}, n, e, f);  // smooth elastic: the normal components swap, the tangential stay
  BOOST_TEST(e.v[0] == 0.0);
  BOOST_TEST(e.v[1] == 1.0);
  BOOST_TEST(f.v[0] == -1.0);
}

BOOST_AUTO_TEST_CASE(no_overlap_with_the_check_after_every_event) {
  compress::GasSetup gas;
  gas.spheres = 108, gas.radius = 0.5, gas.edge = 6.0, gas.lattice = true, gas.speed_max = 1.0;
  EventEngine engine(compress::place_gas(gas, 11), compress::cube(gas.edge));
  engine.check_overlaps(true);
  BOOST_CHECK_NO_THROW(engine.run_events(20000));
  BOOST_TEST(engine.worst_overlap() <= 1e-12);
  // Walls moving in: the seed's run at its largest ratio, checked after every event.
  compress::Compression c;
  c.check_overlaps = true;
  compress::RunResult run;
  BOOST_CHECK_NO_THROW(run = compress::run_compression(c, 3.64, 7));
  BOOST_TEST(run.wall_events > 1000);
}

BOOST_AUTO_TEST_CASE(event_limit_stops_a_run) {
  compress::GasSetup gas;
  gas.spheres = 27, gas.radius = 0.5, gas.edge = 6.0, gas.lattice = true, gas.speed_max = 1.0;
  EventEngine engine(compress::place_gas(gas, 2), compress::cube(gas.edge));
  engine.limit_events(500);
  BOOST_CHECK_THROW(engine.run_events(1000), SolverError);
  BOOST_TEST(engine.counts().pair + engine.counts().wall == 501);
}

BOOST_AUTO_TEST_CASE(overlapping_spheres_are_refused) {
  Spheres s;
  s.add({0, 0, 0}, {0, 0, 0}, 0.5, 1.0);
  s.add({0.9, 0, 0}, {0, 0, 0}, 0.5, 1.0);
  BOOST_CHECK_THROW(EventEngine(s, big_box()), InputError);
  Spheres t;
  t.add({49.8, 0, 0}, {0, 0, 0}, 0.5, 1.0);  // through the wall at 50
  BOOST_CHECK_THROW(EventEngine(t, big_box()), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
