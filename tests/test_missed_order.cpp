// Why an order was missed (dlpverify/missed_order.hpp): the spectral radius by power iteration on
// problems whose eigenvalues are known in closed form, and each reason raised by the evidence that
// shows it, on a study put together by hand (a passing variable gets none).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "dlpverify/missed_order.hpp"

namespace unit_missed_order {

using namespace dlpverify;

namespace {

// dy/dt = −λ_p y with λ = 1, 2, 3, 4, 100 over five members: J = diag(−λ), ρ(J) = 100.
class Decay final : public Problem {
 public:
  std::string name() const override { return "decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  Eigen::Index members() const override { return 5; }
  State initial_state() const override { return State::Constant(5, 1, 1.0); }
  void rhs(double, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) {
      const Eigen::Index p = first + i;
      dydt[0][i] = -(p == 4 ? 100.0 : static_cast<double>(p + 1)) * y[0][i];
    }
  }
};

// A rotation y0′ = ω y1, y1′ = −ω y0 with ω = 7: eigenvalues ±7i, and ‖J v‖ = 7 ‖v‖ for every v.
class Rotation final : public Problem {
 public:
  std::string name() const override { return "rotation"; }
  std::vector<Field> fields() const override { return {{"a", "1"}, {"b", "1"}}; }
  Eigen::Index members() const override { return 3; }
  State initial_state() const override { return State::Constant(3, 2, 1.0); }
  void rhs(double, Eigen::Index, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) {
      dydt[0][i] = 7.0 * y[1][i];
      dydt[1][i] = -7.0 * y[0][i];
    }
  }
};

bool has(const std::vector<MissExplanation>& reasons, MissReason reason) {
  return std::any_of(reasons.begin(), reasons.end(), [reason](const MissExplanation& e) { return e.reason == reason; });
}

}  // namespace

BOOST_AUTO_TEST_SUITE(missed_order)

BOOST_AUTO_TEST_CASE(spectral_radius_of_known_jacobians) {
  const Decay decay;
  BOOST_CHECK_CLOSE(spectral_radius(decay, 0.0, decay.initial_state()), 100.0, 0.1);
  const Rotation rotation;
  BOOST_CHECK_CLOSE(spectral_radius(rotation, 0.0, rotation.initial_state()), 7.0, 0.1);
}

// Two variables over four levels: "a" missed its order with every reason in sight, "b" passed.
BOOST_AUTO_TEST_CASE(each_reason_from_its_evidence) {
  StudyResult study;
  study.plan.t_end = 1.0;
  study.plan.variables = {{"a", 0, 1, "1"}, {"b", 0, 1, "1"}};
  for (int k = 0; k < 4; ++k) {
    LevelResult level;
    level.level = k;
    level.dt = 0.1 / std::pow(2.0, k);
    if (k == 2) level.solver_statistics.nonlinear_convergence_failures = 3;
    study.levels.push_back(level);
  }
  OrderAnalysis a;
  a.status = {LevelStatus::unstable, LevelStatus::ok, LevelStatus::ok, LevelStatus::round_off};
  a.rule = {"error grows", "in the asymptotic range", "in the asymptotic range", "error below its floor"};
  a.fit.valid = true;
  a.fit.levels = {1, 2};
  OrderAnalysis b = a;
  study.orders = {a, b};
  study.reference.error = {1e-6, 0.0};
  study.reference.margin = {5.0, INFINITY};
  study.finest = State::Zero(10, 1);
  CheckVerdict verdict;
  verdict.outcomes = {CheckOutcome::order_miss, CheckOutcome::order_within};
  MissContext context;
  context.spectral_radius = 30.0;  // Δt_0 ρ = 3: beyond the step the fastest scale allows
  context.kinks_inside = 2;
  context.first_kink = 0.3;
  context.last_kink = 0.4;
  context.members = 10;  // the members the kinks were looked for in, whatever state the study kept

  const auto reasons = explain_missed_orders(study, verdict, context);
  BOOST_REQUIRE_EQUAL(reasons.size(), 2u);
  for (MissReason reason : {MissReason::stability, MissReason::round_off, MissReason::reference_accuracy,
                            MissReason::kink, MissReason::inner_iteration})
    BOOST_CHECK_MESSAGE(has(reasons[0], reason), "no " << to_string(reason) << " reason");
  BOOST_CHECK(reasons[1].empty());
  BOOST_CHECK_NE(reasons[0][0].text.find("dt*rho(J) = 3"), std::string::npos);
  const auto kink = std::find_if(reasons[0].begin(), reasons[0].end(), [](const auto& r) { return r.reason == MissReason::kink; });
  BOOST_CHECK(kink != reasons[0].end() && kink->text.find("2 of 10 members") != std::string::npos);

  // Without the evidence, no reason: a missed order whose cause cannot be seen says nothing.
  study.orders[0].status = {LevelStatus::ok, LevelStatus::ok, LevelStatus::ok, LevelStatus::ok};
  study.orders[0].fit.levels = {0, 1, 2, 3};
  study.reference.margin[0] = 1e6;
  study.levels[2].solver_statistics = {};
  context = MissContext{};
  BOOST_CHECK(explain_missed_orders(study, verdict, context)[0].empty());
}

// The resolved step is Δt·ρ(J) = 1 (docs/verification.md, "Why an order was missed"), not an
// explicit method's stability limit of about 2: on Decay (ρ = 100, estimated within 0.1%) a study
// whose levels are all ok but whose coarsest fitted level has Δt_0 = 0.015 (Δt·ρ = 1.5) is given
// the stability reason; Δt_0 = 0.0095 (0.95) is not.
BOOST_AUTO_TEST_CASE(stability_above_one_step_per_time_scale) {
  const Decay decay;
  const MissContext context = miss_context(decay, 1.0);
  BOOST_REQUIRE_CLOSE(context.spectral_radius, 100.0, 0.1);
  for (double coarsest : {0.015, 0.0095}) {
    StudyResult study;
    study.plan.t_end = 1.0;
    study.plan.variables = {{"y", 0, 1, "1"}};
    for (int k = 0; k < 3; ++k) {
      LevelResult level;
      level.level = k;
      level.dt = coarsest / std::pow(2.0, k);
      study.levels.push_back(level);
    }
    OrderAnalysis a;
    a.status.assign(3, LevelStatus::ok);
    a.rule.assign(3, "in the asymptotic range");
    a.fit.valid = true;
    a.fit.levels = {0, 1, 2};
    study.orders = {a};
    study.reference.error = {0.0};
    study.reference.margin = {INFINITY};
    study.finest = State::Zero(5, 1);
    CheckVerdict verdict;
    verdict.outcomes = {CheckOutcome::order_miss};
    const auto reasons = explain_missed_orders(study, verdict, context);
    BOOST_REQUIRE_EQUAL(reasons.size(), 1u);
    const bool beyond = coarsest * 100.0 > 1.0;
    BOOST_CHECK_MESSAGE(has(reasons[0], MissReason::stability) == beyond,
                        "dt*rho = " << coarsest * context.spectral_radius << ": stability reason "
                                    << (beyond ? "missing" : "given"));
    if (beyond && !reasons[0].empty()) BOOST_CHECK_NE(reasons[0][0].text.find("dt*rho(J) = 1.5"), std::string::npos);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_missed_order
