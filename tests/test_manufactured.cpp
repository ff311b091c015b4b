// Manufactured solutions (include/dlpverify/manufactured.hpp, docs/verification.md "Manufactured
// solutions"): y′ = f(t, y) + ŷ′(t) − f(t, ŷ(t)) has the exact solution ŷ for any f.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <memory>

#include "dlp_support.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/dlp.hpp"
#include "dlpverify/manufactured.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/reference_study.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/study.hpp"
#include "problems/dlp/case.hpp"
#include "problems/thermal/cooling.hpp"

namespace unit_manufactured {

using namespace dlpverify;
using namespace dlpverify::dlp;

namespace {

// An autonomous problem of the test's own: y′ = −λ_p y with λ_p = 1 + p/N, fields y (starting at
// 1 + p/N) and z (starting at 0, so its trajectory is the 1 − cos branch).
class Decay final : public Problem {
 public:
  std::string name() const override { return "decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}, {"z", "1"}}; }
  Eigen::Index members() const override { return 10; }
  State initial_state() const override {
    State y(10, 2);
    for (Eigen::Index p = 0; p < 10; ++p) {
      y(p, 0) = 1.0 + static_cast<double>(p) / 10.0;
      y(p, 1) = 0.0;
    }
    return y;
  }
  void rhs(double, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) {
      const double rate = 1.0 + static_cast<double>(first + i) / 10.0;
      dydt[0][i] = -rate * y[0][i];
      dydt[1][i] = -rate * y[1][i];
    }
  }
};

// The midpoint rule with its node slipped to c₂ = 0.6 (a₂₁ = 1/2): order 2 on an autonomous
// problem, first order once t enters the right-hand side (Σ b_i c_i = 0.6 ≠ 1/2).
constexpr ButcherTableau<2> slipped{{{{0.0, 0.0}, {0.5, 0.0}}}, {0.0, 1.0}, {0.0, 0.6}, 2};

StudyPlan plan(double t_end, double dt, int levels) {
  StudyPlan p;
  p.t_end = t_end;
  p.coarsest_dt = dt;
  p.levels = levels;
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(manufactured)

// ŷ′ is the family's own derivative: an 8th-order central difference of the closed form agrees to
// ~1e-10 relative; and g(t, ŷ(t)) = ŷ′(t), the defining property, to round-off.
BOOST_AUTO_TEST_CASE(the_trajectory_solves_the_manufactured_problem) {
  const Decay decay;
  const ManufacturedProblem m(decay, 2.0);
  const State y0 = m.initial_state();
  BOOST_TEST((y0 == decay.initial_state()).all());
  for (double tau : {0.0, 0.37, 1.2, 2.0}) {
    const double h = 1e-3;
    const State plus = closed_form(m, y0, tau + h), minus = closed_form(m, y0, tau - h);
    const State plus2 = closed_form(m, y0, tau + 2 * h), minus2 = closed_form(m, y0, tau - 2 * h);
    const State at = closed_form(m, y0, tau);
    // g(t, ŷ) through the block rhs, 10 members at once.
    std::vector<const double*> in{at.col(0).data(), at.col(1).data()};
    State g(10, 2);
    std::vector<double*> out{g.col(0).data(), g.col(1).data()};
    m.rhs(tau, 0, 10, in.data(), out.data());
    for (Eigen::Index p = 0; p < 10; ++p)
      for (int f = 0; f < 2; ++f) {
        double value = 0.0, rate = 0.0;
        m.trajectory(p, f, tau, value, rate);
        BOOST_TEST(value == at(p, f));
        // 4th-order central difference (the O(h⁴) error at h = 1e-3 is ~1e-11 of these rates).
        const double difference = (8.0 * (plus(p, f) - minus(p, f)) - (plus2(p, f) - minus2(p, f))) / (12.0 * h);
        BOOST_TEST(std::abs(difference - rate) <= 1e-8 * (1.0 + std::abs(rate)), "p " << p << " f " << f << " τ " << tau);
        BOOST_TEST(std::abs(g(p, f) - rate) <= 1e-14 * (1.0 + std::abs(rate)) + 1e-14 * std::abs(at(p, f)));
      }
  }
}

// Off the trajectory the source is evaluated at ŷ, not at y: for Decay, f(t, y) = −λ_p y, so
//   g(t, y) = −λ_p y + ŷ′(t) + λ_p ŷ(t),
// which depends on y (g(y) − g(ŷ) = −λ_p (y − ŷ)). A source f(t, y) would leave g = ŷ′(t) for
// every y: a quadrature, blind to the order conditions that couple the stages.
BOOST_AUTO_TEST_CASE(off_the_trajectory_the_source_is_taken_at_the_trajectory) {
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  const Decay decay;
  const ManufacturedProblem m(decay, 2.0);
  for (double tau : {0.0, 0.37, 1.2}) {
    const State at = closed_form(m, m.initial_state(), tau);
    State y(10, 2);
    for (Eigen::Index p = 0; p < 10; ++p) {
      y(p, 0) = 1.3 * at(p, 0) + 0.05;   // y ≠ ŷ in both fields, by a different amount per member
      y(p, 1) = at(p, 1) - 0.02 * static_cast<double>(p + 1);
    }
    std::vector<const double*> in{y.col(0).data(), y.col(1).data()};
    State g(10, 2);
    std::vector<double*> out{g.col(0).data(), g.col(1).data()};
    m.rhs(tau, 0, 10, in.data(), out.data());
    for (Eigen::Index p = 0; p < 10; ++p) {
      const double lambda = 1.0 + static_cast<double>(p) / 10.0;
      for (int f = 0; f < 2; ++f) {
        double value = 0.0, rate = 0.0;
        m.trajectory(p, f, tau, value, rate);
        const double expected = -lambda * y(p, f) + rate + lambda * value;
        // A few roundings on each side, each at most ε/2 of the largest term.
        const double scale = lambda * std::abs(y(p, f)) + std::abs(rate) + lambda * std::abs(value);
        BOOST_TEST(std::abs(g(p, f) - expected) <= 4 * kEpsilon * scale,
                   "p " << p << " f " << f << " τ " << tau << ": g " << g(p, f) << ", expected " << expected);
        BOOST_TEST(std::abs(g(p, f) - rate) > 1e-3);  // |λ_p (y − ŷ)| ≥ 0.02 here
      }
    }
  }
}

// Signs are kept: a positive field stays positive (min over the study above y0 e^(−2A)); the field
// starting at zero stays ≥ 0 and moves (A s_f (1 − cos): up to 2A s_f).
BOOST_AUTO_TEST_CASE(positive_fields_stay_positive_and_zero_fields_move) {
  const Decay decay;
  const ManufacturedProblem m(decay, 1.0);
  const State y0 = m.initial_state();
  double largest_z = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const State at = closed_form(m, y0, k / 200.0);
    BOOST_TEST((at.col(0) >= y0.col(0) * std::exp(-2.0 * kManufacturedAmplitude) * (1.0 - 1e-15)).all());
    BOOST_TEST((at.col(1) >= 0.0).all());
    largest_z = std::max(largest_z, at.col(1).maxCoeff());
  }
  // s_f of z is 1 (zero everywhere: 1 in SI units), so z reaches 2A = 0.2 at half a turn.
  BOOST_TEST(largest_z > 0.19);
  BOOST_TEST(largest_z <= 0.2 + 1e-15);
}

// On an autonomous problem the slipped node is invisible against the closed form and first order
// against the manufactured solution; rk2 is order 2 against both.
BOOST_AUTO_TEST_CASE(a_slipped_node_shows_only_on_the_manufactured_problem) {
  const Decay decay;
  ExplicitRungeKutta<slipped> slip("slipped");
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  ReferenceSettings manufactured;
  manufactured.kind = ReferenceKind::manufactured;
  const StudyResult slip_manufactured = run_study(decay, slip, plan(1.0, 0.05, 5), manufactured);
  const StudyResult rk2_manufactured = run_study(decay, rk2, plan(1.0, 0.05, 5), manufactured);
  BOOST_TEST(slip_manufactured.reference.error == std::vector<double>(2, 0.0));
  for (const OrderAnalysis& o : slip_manufactured.orders) BOOST_TEST(std::abs(o.fit.value - 1.0) < 0.15, o.fit.value);
  for (const OrderAnalysis& o : rk2_manufactured.orders) BOOST_TEST(std::abs(o.fit.value - 2.0) < 0.1, o.fit.value);
  BOOST_TEST(!check_orders(slip_manufactured, 2.0, 0.1).passed());
  BOOST_TEST(check_orders(rk2_manufactured, 2.0, 0.1).passed());
}

// A problem that is manufactured already is studied as it is, not wrapped twice: the same errors
// bit for bit as the problem handed over raw (wrapped over the same duration inside the study),
// while the problem's own exact closed form is no manufactured one.
BOOST_AUTO_TEST_CASE(a_manufactured_problem_is_not_wrapped_again) {
  const Decay decay;
  const ManufacturedProblem m(decay, 1.0);
  BOOST_TEST(is_manufactured(m));
  BOOST_TEST(!is_manufactured(decay));
  const auto drag = make_problem("drag", {.outer = 3});
  BOOST_TEST(has_closed_form(*drag));
  BOOST_TEST(!is_manufactured(*drag));
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  ReferenceSettings manufactured;
  manufactured.kind = ReferenceKind::manufactured;
  const StudyResult raw = run_study(decay, rk2, plan(1.0, 0.05, 3), manufactured);
  const StudyResult given = run_study(m, rk2, plan(1.0, 0.05, 3), manufactured);
  BOOST_TEST_REQUIRE(raw.levels.size() == given.levels.size());
  for (std::size_t l = 0; l < raw.levels.size(); ++l)
    for (std::size_t v = 0; v < raw.levels[l].norms.size(); ++v)
      BOOST_TEST(raw.levels[l].norms[v].l2 == given.levels[l].norms[v].l2);
}

// What the wrapper keeps and declines: inert fields stay inert (constant trajectory, zero source)
// and the DLP cloud's fused stepper is declined (it would bypass the source), with the same bits
// as stepping the manufactured problem through its rhs.
BOOST_AUTO_TEST_CASE(inert_fields_kept_and_fused_steps_declined) {
  const test::PhysicsProblem p({Parameters{}, find_case("drag").terms}, test::varied_cloud(70, 3));
  BOOST_REQUIRE(p.problem->capability<FusedStepper>() != nullptr);
  const ManufacturedProblem m(*p, 1e-3);
  BOOST_TEST(m.capability<FusedStepper>() == nullptr);
  BOOST_TEST(m.capability<SolutionKinks>() == nullptr);
  BOOST_TEST(inert_fields(m) == inert_fields(*p));
  const State y0 = m.initial_state();
  const State later = closed_form(m, y0, 0.7e-3);
  BOOST_TEST((later.col(TEMPERATURE) == y0.col(TEMPERATURE)).all());
  BOOST_TEST((later.col(MASS) == y0.col(MASS)).all());
  BOOST_TEST(!(later.col(VX) == y0.col(VX)).all());
}

// The linear decay of the cooling particles passes through: the source does not depend on y.
BOOST_AUTO_TEST_CASE(linear_decay_passes_through) {
  const thermal::CoolingProblem cooling("cooling", thermal::CoolingPhysics{}, thermal::CoolingPopulation{20});
  const ManufacturedProblem m(cooling, 0.5);
  BOOST_REQUIRE(m.capability<LinearDecay>() != nullptr);
  State ours(5, 1), theirs(5, 1);
  double* a[] = {ours.data()};
  double* b[] = {theirs.data()};
  m.capability<LinearDecay>()->linear_decay(7, 5, a);
  cooling.capability<LinearDecay>()->linear_decay(7, 5, b);
  BOOST_TEST((ours == theirs).all());
}

BOOST_AUTO_TEST_CASE(a_duration_that_is_not_positive_is_refused) {
  const Decay decay;
  BOOST_CHECK_THROW(ManufacturedProblem(decay, 0.0), InputError);
  BOOST_CHECK_THROW(ManufacturedProblem(decay, std::nan("")), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_manufactured
