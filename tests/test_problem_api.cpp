// The harness needs no DLP: a problem of the test's own — N decaying members y' = −λ_p y with a
// per-member rate λ_p = 1 + p/N, closed form y0 e^(−λ_p τ) — through the Runge–Kutta family, the
// study loop, check, and a CVODE reference solved in blocks of members (which must hand each
// block its members' own indices: a block-offset slip would give every block the first rates).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>
#include <tuple>

#include "dlpverify/case_report.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/reference_study.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/study.hpp"

namespace unit_problem_api {

using namespace dlpverify;

namespace {

class Decay final : public Problem, public ClosedForm {
 public:
  explicit Decay(Eigen::Index members) : members_(members) { provide<ClosedForm>(*this); }
  std::string name() const override { return "decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  std::vector<Variable> variables() const override { return {{"amount", 0, 1, "1"}}; }
  Eigen::Index members() const override { return members_; }
  double initial_time() const override { return 0.5; }
  State initial_state() const override { return State::Constant(members_, 1, 2.0); }
  double rate(Eigen::Index p) const { return 1.0 + static_cast<double>(p) / static_cast<double>(members_); }
  void rhs(double, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = -rate(first + i) * y[0][i];
  }
  std::string formula() const override { return "y0 exp(-lambda_p t)"; }
  State solution(Eigen::Index first, const State& initial, double tau) const override {
    State y(initial.rows(), 1);
    for (Eigen::Index p = 0; p < initial.rows(); ++p) y(p, 0) = initial(p, 0) * std::exp(-rate(first + p) * tau);
    return y;
  }

 private:
  Eigen::Index members_;
};

}  // namespace

BOOST_AUTO_TEST_SUITE(problem_api)

BOOST_AUTO_TEST_CASE(rk4_on_a_problem_of_its_own) {
  const Decay decay(100);  // 100 members: three blocks of 32 and a partial one
  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.levels = 4;
  const StudyResult study = run_study(decay, rk4, plan);
  BOOST_REQUIRE(study.orders.size() == 1u);
  // Measured: 4.061 over Δt = 0.1 … 0.0125 (still slightly pre-asymptotic at λΔt = 0.2).
  BOOST_TEST(std::abs(study.orders[0].fit.value - 4.0) < 0.1, "fitted " << study.orders[0].fit.value);
  BOOST_TEST(check_orders(study, 4.0, 0.1).passed());
  BOOST_TEST(!check_orders(study, 2.0, 0.1).passed());
}

// The reports count a problem's members in its own words (MemberNoun), and a problem without the
// capability has members: one of them is "1 member", never "1 particles".
BOOST_AUTO_TEST_CASE(reports_count_members_in_the_problem_s_words) {
  const Decay one(1);
  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.levels = 2;
  StudyDescription d;
  d.particles = 1;
  d.member_nouns = member_nouns(one);
  const StudyResult study = run_study(one, rk4, plan);
  BOOST_TEST(format_table(d, study, std::nullopt).find("\n1 member · t0 = ") != std::string::npos);
  BOOST_TEST(to_json(d, study, std::nullopt)["member_noun"] == "member");
  BOOST_TEST(count_text(9100, member_nouns(Decay(9100))) == "9100 members");
  BOOST_TEST(count_text(2, MemberNouns{"parcel", "parcels"}) == "2 parcels");
}

// A plan the study cannot run is refused by the API, naming what is wrong, before any work: no
// levels (it crashed on the empty list of levels), a ratio of 1 (it fitted "order -nan") and a
// ratio below 1 (it ran levels growing coarser).
BOOST_AUTO_TEST_CASE(a_plan_without_levels_or_refinement_is_refused) {
  const Decay decay(4);
  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  ReferenceSettings exact;
  exact.kind = ReferenceKind::exact;
  for (const auto& [levels, ratio, quantity] : {std::tuple{0, 2.0, "levels"}, std::tuple{1, 2.0, "levels"},
                                                std::tuple{3, 1.0, "step ratio"}, std::tuple{3, 0.5, "step ratio"}}) {
    StudyPlan plan;
    plan.t_end = 1.0;
    plan.coarsest_dt = 0.25;
    plan.levels = levels;
    plan.ratio = ratio;
    const auto names = [quantity = std::string(quantity)](const InputError& e) { return e.quantity() == quantity; };
    BOOST_CHECK_EXCEPTION(run_study(decay, rk4, plan), InputError, names);
    BOOST_CHECK_EXCEPTION(run_study(decay, rk4, plan, exact), InputError, names);
  }
}

BOOST_AUTO_TEST_CASE(cvode_reference_in_blocks_keeps_each_member_its_rate) {
  const Decay decay(3000);  // three blocks of 1024 members, the last partial
  ReferenceSettings settings;
  settings.kind = ReferenceKind::cvode;
  settings.rtol = 1e-12;
  const State initial = decay.initial_state();
  const Reference reference = compute_reference(decay, settings, initial, 1.0, decay.variables());
  const State exact = closed_form(decay, initial, 1.0);
  // Member 2999 decays at λ = 1.9997: e^(−1.9997) · 2 = 0.27075…; with member 2999 − 2048's
  // rate it would be 0.4556…: a block-offset slip is a relative error of order one.
  double worst = 0.0;
  for (Eigen::Index p = 0; p < exact.rows(); ++p)
    worst = std::max(worst, std::abs(reference.state(p, 0) - exact(p, 0)) / exact(p, 0));
  BOOST_TEST(worst < 1e-9, "largest relative error " << worst);
  BOOST_TEST(reference.error_estimate.size() == 1u);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_problem_api
