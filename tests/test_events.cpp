// The event-driven hard-sphere engine of docs/model.md §7.2 (src/problems/spheres):
//   - a head-on collision worked out by hand: its time from the quadratic, the outgoing
//     velocities of unequal masses from momentum and energy conservation;
//   - the stable root against a long-double evaluation of the textbook root, near contact;
//   - a wall moving at u reflects v' = 2u − v, at the time the gap closes;
//   - with the walls at rest, kinetic energy is conserved to round-off over 10⁶ events (N = 108,
//     packing fraction 0.26), and so is the total energy of perfectly rough elastic spheres;
//   - the full collision model (restitution, sticking and sliding friction, spin) by hand;
//   - no pair ever overlaps with the overlap check after every event (walls at rest and moving),
//     and overlapping spheres are refused;
//   - what every event must keep (momentum, energy, separation; the speed seen from a wall) on
//     outcomes by hand, right and slipped; kinetic theory's event rate by hand; the work bound
//     (events in all, events per simulated second) stops a run with its reason.
// Each run has a tight work bound (kTight: a handful of events where one or two are expected, 10 ×
// kinetic theory's rate), so a slip that makes events pile up fails in seconds, with its reason.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "problems/spheres/compression.hpp"
#include "problems/spheres/event_rate.hpp"
#include "problems/spheres/gas_setup.hpp"
#include "dlpverify/errors.hpp"
#include "problems/spheres/engine.hpp"
#include "problems/spheres/event_times.hpp"
#include "problems/spheres/invariants.hpp"

namespace unit_events {

using namespace dlpverify;
using namespace dlpverify::events;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

Box big_box() { return compress::cube(100.0); }

// No run here needs more than twice kinetic theory's rate.
constexpr WorkBound kTight{0, 10.0};

bool says(const std::exception& e, const std::string& text) {
  const bool found = std::string(e.what()).find(text) != std::string::npos;
  if (!found) BOOST_TEST_MESSAGE("the error '" << e.what() << "' does not say '" << text << "'");
  return found;
}

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
  engine.bound_work({10, 10.0});  // one collision expected
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
  engine.bound_work({10, 10.0});  // one wall hit expected
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
  engine.bound_work(kTight);
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
  engine.bound_work(kTight);
  engine.check_overlaps(true);
  BOOST_CHECK_NO_THROW(engine.run_events(20000));
  BOOST_TEST(engine.worst_overlap() <= 1e-12);
  // Walls moving in: the seed's run at its largest ratio, checked after every event.
  compress::Compression c;
  c.check_overlaps = true;
  c.work_bound = {10000, 10.0};  // the run needs 2504 events
  compress::RunResult run;
  BOOST_CHECK_NO_THROW(run = compress::run_compression(c, 3.64, 7));
  BOOST_TEST(run.wall_events > 1000);
}

// The work bound's event count: the 501st event of a run bounded at 500 stops it, and says so.
BOOST_AUTO_TEST_CASE(work_bound_stops_a_run_past_its_events) {
  compress::GasSetup gas;
  gas.spheres = 27, gas.radius = 0.5, gas.edge = 6.0, gas.lattice = true, gas.speed_max = 1.0;
  EventEngine engine(compress::place_gas(gas, 2), compress::cube(gas.edge));
  engine.bound_work({500, 0.0});
  BOOST_CHECK_EXCEPTION(engine.run_events(1000), SolverError, [](const SolverError& e) {
    return says(e, "after 501 events") && says(e, "past the bound of 500 events");
  });
  BOOST_TEST(engine.counts().pair + engine.counts().wall == 501);
}

// Kinetic theory's rate by hand. Two spheres R = 0.5 (σ = 1), v = ±(1, 0, 0), in a cube of 10:
// walls 2 · 1/(10 − 1); pairs ½ · 2 · 1/V · π σ² · √(2⟨v²⟩) · g(η), ⟨v²⟩ = 1, V = 1000,
// η = 2 (4/3) π 0.5³ / V = π/3000, g = (1 − η/2)/(1 − η)³.
BOOST_AUTO_TEST_CASE(kinetic_theory_rate_by_hand) {
  Spheres s;
  s.add({-2, 0, 0}, {1, 0, 0}, 0.5, 1.0);
  s.add({2, 0, 0}, {-1, 0, 0}, 0.5, 1.0);
  const EventEngine engine(s, compress::cube(10.0));
  const double eta = std::numbers::pi / 3000.0, g = (1.0 - eta / 2.0) / std::pow(1.0 - eta, 3);
  const double pairs = 1.0 / 1000.0 * std::numbers::pi * std::sqrt(2.0) * g;
  BOOST_TEST(engine.kinetic_theory_rate() == 2.0 / 9.0 + pairs, boost::test_tools::tolerance(1e-14));
}

// The work bound's rate: one sphere (R 0.5, v_x = 1) rattling between x walls 1.1 apart hits one
// every 0.1 s, first at 0.05 s: exactly kinetic theory's Γ = |v_x|/(L − 2R) = 10 events/s. Its
// first window of 1000 events lasts 99.95 s: bounded at 2 Γ (≥ 50 s needed) it runs on, to 2000
// hits by t = 200 s; bounded at 0.5 Γ (≥ 200 s needed) the 1000th event stops it, with the reason.
BOOST_AUTO_TEST_CASE(work_bound_on_events_per_simulated_second) {
  Spheres s;
  s.add({0, 0, 0}, {1, 0, 0}, 0.5, 1.0);
  const Box box{{-0.55, -5, -5}, {0.55, 5, 5}, {}, {}};
  EventEngine fast_enough(s, box);
  BOOST_TEST(fast_enough.kinetic_theory_rate() == 10.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(fast_enough.rate_window() == 1000);
  fast_enough.bound_work({0, 2.0});
  BOOST_CHECK_NO_THROW(fast_enough.run_until(200.0));
  BOOST_TEST(fast_enough.counts().wall == 2000);
  EventEngine too_fast(s, box);
  too_fast.bound_work({0, 0.5});
  BOOST_CHECK_EXCEPTION(too_fast.run_until(200.0), SolverError, [](const SolverError& e) {
    return says(e, "after 1000 events") && says(e, "1000 events in the last") && says(e, "(from t = 0 s)") &&
           says(e, "0.5 x the kinetic-theory rate 10 events/s");
  });
  BOOST_TEST(too_fast.counts().wall == 1000);
}

// What every event must keep, on outcomes worked out by hand. Head-on along x, a (m 1) at v 2
// left of b (m 3) at rest, n = (−1, 0, 0): elastic, v_a' = −1, v_b' = 1. Slips: the impulse
// doubled (v_a' = −4, v_b' = 2: momentum kept, energy 2 → 14); b given a's share (v_b' = 3:
// momentum 2 → 8); no impulse at all, as with the normal reversed (still approaching). With
// e = 0.5, J = 1.5 · 2 / (1 + 1/3) = 2.25: v_a' = −0.25, v_b' = 0.75, energy 2 → 0.875, v_n' = 1.
BOOST_AUTO_TEST_CASE(pair_invariants_by_hand) {
  const double n[3] = {-1, 0, 0};
  const SphereKinematics a{{2, 0, 0}, {0, 0, 0}, 1.0, 0.5}, b{{0, 0, 0}, {0, 0, 0}, 3.0, 0.5};
  auto after = [](const SphereKinematics& s, double vx) { return SphereKinematics{{vx, 0, 0}, {0, 0, 0}, s.mass, s.radius}; };
  const CollisionModel elastic{}, half{0.5, -1.0, 0.0};
  BOOST_TEST(pair_violation(elastic, n, a, b, after(a, -1), after(b, 1)) == "");
  BOOST_TEST(pair_violation(elastic, n, a, b, after(a, -4), after(b, 2)).find("kinetic energy went from 2 to 14") !=
             std::string::npos);
  BOOST_TEST(pair_violation(elastic, n, a, b, after(a, -1), after(b, 3)).find("momentum changed by 6.000e+00") !=
             std::string::npos);
  BOOST_TEST(pair_violation(elastic, n, a, b, a, b).find("still approach") != std::string::npos);
  BOOST_TEST(pair_violation(half, n, a, b, after(a, -0.25), after(b, 0.75)) == "");
  BOOST_TEST(pair_violation(elastic, n, a, b, after(a, -0.25), after(b, 0.75)).find("keep it") != std::string::npos);
  // The rule itself keeps them: the full model (sticking, spin) of rough_collision_by_hand.
  const double x[3] = {1, 0, 0};
  SphereKinematics c{{-1, 1, 0}, {0, 0, 0}, 1.0, 1.0}, d{{0, 0, 0}, {0, 0, 0}, 1.0, 1.0};
  const SphereKinematics c0 = c, d0 = d;
  collide({1.0, 1.0, 1e6}, x, c, d);
  BOOST_TEST(pair_violation({1.0, 1.0, 1e6}, x, c0, d0, c, d) == "");
}

// A wall moving at u reflects v' = 2u − v: upper wall at u = −0.5, v = 3 → −4; reflected as if at
// rest (−3), the speed seen from the wall goes 3.5 → 2.5. A lower wall at u = 0.2 meeting a sphere
// at rest gives it 0.4; reflected as if at rest (−0) the sphere is still closing on the wall.
BOOST_AUTO_TEST_CASE(wall_invariants_by_hand) {
  BOOST_TEST(wall_violation(3.0, -4.0, -0.5, false) == "");
  BOOST_TEST(wall_violation(3.0, -3.0, -0.5, false).find("went from 3.5 to 2.5") != std::string::npos);
  BOOST_TEST(wall_violation(0.0, 0.4, 0.2, true) == "");
  BOOST_TEST(wall_violation(0.0, -0.0, 0.2, true).find("still approaches") != std::string::npos);
  BOOST_TEST(wall_violation(-2.0, 2.0, 0.0, true) == "");  // at rest: v' = −v, kinetic energy kept
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

}  // namespace unit_events
