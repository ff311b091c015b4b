// The reference is measured like every level: a study of a problem whose measured columns include
// a derived quantity gives the same norms whichever way the study is built — the public entry
// point with any reference kind, the closed-form overload, or by hand (compute_reference, then
// Problem::measured, then the harness's run_study). A reference compared through its raw fields
// would set an energy against a velocity.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <memory>

#include "study/journal.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/reference_study.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/study.hpp"

namespace unit_reference_value {

using namespace dlpverify;

namespace {

// Harmonic oscillators x″ = −x, member p from x0 = 1 + p/N, v0 = 1/2. Closed form:
// x = x0 cos τ + v0 sin τ, v = −x0 sin τ + v0 cos τ. Measured columns: the position and the
// energy E = ½v² + ½x² (conserved: E(τ) = E(0)). The energy takes the velocity's column, so a
// reference compared through its raw fields sets E against v — a wrong number, not a read past
// the end of the state.
class Oscillators final : public Problem, public ClosedForm {
 public:
  explicit Oscillators(Eigen::Index members) : members_(members) { provide<ClosedForm>(*this); }
  std::string name() const override { return "oscillators"; }
  std::vector<Field> fields() const override { return {{"x", "1"}, {"v", "1"}}; }
  std::vector<Variable> variables() const override { return {{"position", 0, 1, "1"}, {"energy", 1, 1, "1"}}; }
  State measured(State state, double, Eigen::Index = 0) const override {
    state.col(1) = 0.5 * state.col(1).square() + 0.5 * state.col(0).square();
    return state;
  }
  Eigen::Index members() const override { return members_; }
  double initial_time() const override { return 0.0; }
  State initial_state() const override {
    State y(members_, 2);
    for (Eigen::Index p = 0; p < members_; ++p) {
      y(p, 0) = x0(p);
      y(p, 1) = 0.5;
    }
    return y;
  }
  void rhs(double, Eigen::Index, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) {
      dydt[0][i] = y[1][i];
      dydt[1][i] = -y[0][i];
    }
  }
  std::string formula() const override { return "x = x0 cos t + v0 sin t"; }
  State solution(Eigen::Index, const State& initial, double tau) const override {
    State y(initial.rows(), 2);
    y.col(0) = initial.col(0) * std::cos(tau) + initial.col(1) * std::sin(tau);
    y.col(1) = -initial.col(0) * std::sin(tau) + initial.col(1) * std::cos(tau);
    return y;
  }
  double x0(Eigen::Index p) const { return 1.0 + static_cast<double>(p) / static_cast<double>(members_); }

 private:
  Eigen::Index members_;
};

// The same oscillators without a closed form, so that no path can fall back on it.
class OscillatorsWithoutClosedForm final : public Problem {
 public:
  explicit OscillatorsWithoutClosedForm(Eigen::Index members) : inner_(members) {}
  std::string name() const override { return "oscillators without closed form"; }
  std::vector<Field> fields() const override { return inner_.fields(); }
  std::vector<Variable> variables() const override { return inner_.variables(); }
  State measured(State state, double tau, Eigen::Index first = 0) const override {
    return inner_.measured(std::move(state), tau, first);
  }
  Eigen::Index members() const override { return inner_.members(); }
  double initial_time() const override { return inner_.initial_time(); }
  State initial_state() const override { return inner_.initial_state(); }
  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    inner_.rhs(t, first, count, y, dydt);
  }

 private:
  Oscillators inner_;
};

StudyPlan plan_of_four_levels() {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.levels = 4;
  return plan;
}

double energy_reference_l2(const Oscillators& problem);

// The harness's own run_study, the reference measured by hand (and handed back in `measured_reference`).
StudyResult by_hand(const Problem& problem, Integrator& integrator, const ReferenceSettings& settings,
                    State* measured_out = nullptr) {
  StudyPlan plan = plan_of_four_levels();
  plan.variables = problem.variables();
  plan.expected_order = integrator.order();
  const Reference reference = compute_reference(problem, settings, problem.initial_state(), plan.t_end, plan.variables);
  const State measured_reference = problem.measured(reference.state, plan.t_end);
  const Solve solve = [&](double dt, long steps, SolverStatistics& statistics) {
    State state = problem.initial_state();
    integrator.advance(problem, state, problem.initial_time(), dt, steps);
    statistics = integrator.statistics();
    return problem.measured(state, plan.t_end);
  };
  if (measured_out) *measured_out = measured_reference;
  return run_study(plan, measured_reference, reference.error_estimate, solve);
}

// The measured closed form at t = 1, written out here: x = x0 cos 1 + v0 sin 1, E = E(0).
State measured_closed_form(const Oscillators& problem) {
  State y(problem.members(), 2);
  for (Eigen::Index p = 0; p < problem.members(); ++p) {
    y(p, 0) = problem.x0(p) * std::cos(1.0) + 0.5 * std::sin(1.0);
    y(p, 1) = 0.5 * 0.25 + 0.5 * problem.x0(p) * problem.x0(p);
  }
  return y;
}

// A study against an approximate reference r and one against the closed form e differ, per
// variable, by at most ‖r − e‖ (the triangle inequality of the L2 norm), whatever the kind.
void require_within_reference_distance(const StudyResult& approximate, const StudyResult& closed_form,
                                       const State& reference, const Oscillators& problem) {
  const State exact = measured_closed_form(problem);
  for (int v = 0; v < 2; ++v) {
    const double distance = std::sqrt((reference.col(v) - exact.col(v)).square().sum());
    BOOST_TEST(distance < 1e-8, "variable " << v << ": reference " << distance << " from the closed form");
    const double a = approximate.levels.back().norms[static_cast<std::size_t>(v)].l2;
    const double b = closed_form.levels.back().norms[static_cast<std::size_t>(v)].l2;
    BOOST_TEST(std::abs(a - b) <= distance * (1.0 + 1e-9) + 1e-15, "variable " << v << ": " << a << " vs " << b);
  }
}

// The midpoint rule on x″ = −x multiplies (x, v) by a matrix of determinant |R(ih)|² = 1 + h⁴/4
// per step, R(z) = 1 + z + z²/2, and E is ½ of the squared norm: after n = 1/h steps
// E = E(0) (1 + h⁴/4)^n, an error of order h³ (not 2). The finest level's energy L2 error is
// √Σ E_p(0)² · ((1 + h⁴/4)^n − 1).
double midpoint_energy_error(const Oscillators& problem, double h, long n) {
  return energy_reference_l2(problem) * std::expm1(static_cast<double>(n) * std::log1p(h * h * h * h / 4.0));
}

// Every level's every norm, bit for bit: both studies run the same arithmetic in the same order
// (the same reference solve, the same measured(), the same levels), so any difference, however
// small, is a different computation — no tolerance is needed or wanted.
void require_same_norms(const StudyResult& a, const StudyResult& b) {
  BOOST_REQUIRE_EQUAL(a.levels.size(), b.levels.size());
  for (std::size_t k = 0; k < a.levels.size(); ++k) {
    BOOST_REQUIRE_EQUAL(a.levels[k].norms.size(), b.levels[k].norms.size());
    for (std::size_t v = 0; v < a.levels[k].norms.size(); ++v) {
      BOOST_TEST(a.levels[k].norms[v].l2 == b.levels[k].norms[v].l2, "level " << k << " variable " << v);
      BOOST_TEST(a.levels[k].norms[v].max == b.levels[k].norms[v].max, "level " << k << " variable " << v);
      BOOST_TEST(a.levels[k].norms[v].reference_l2 == b.levels[k].norms[v].reference_l2, "level " << k << " variable " << v);
    }
  }
  for (std::size_t v = 0; v < a.reference.error.size(); ++v) BOOST_TEST(a.reference.error[v] == b.reference.error[v]);
}

// The energy's reference size, computed here from E(τ) = E(0) = ½v0² + ½x0², independently of
// every path: √Σ_p E_p².
double energy_reference_l2(const Oscillators& problem) {
  double sum = 0.0;
  for (Eigen::Index p = 0; p < problem.members(); ++p) {
    const double energy = 0.5 * 0.25 + 0.5 * problem.x0(p) * problem.x0(p);
    sum += energy * energy;
  }
  return std::sqrt(sum);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(reference_value)

// Exact: the entry point, the closed-form overload and the hand-built study agree bit for bit; the
// energy's reference size is the conserved E(0) (to round-off of cos²+sin², 1e-14 relative), and
// its finest error and order are the midpoint rule's closed form (midpoint_energy_error, order 3)
// — the raw-field comparison gives order ≈ 0 (the error is then ‖E − v‖, dominated by the gap
// between two different quantities).
BOOST_AUTO_TEST_CASE(exact_reference_measures_a_derived_variable) {
  const Oscillators problem(40);
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  ReferenceSettings exact;
  exact.kind = ReferenceKind::exact;
  const StudyResult entry = run_study(problem, rk2, plan_of_four_levels(), exact);
  const StudyResult closed_form = run_study(problem, rk2, plan_of_four_levels());
  const StudyResult hand = by_hand(problem, rk2, exact);
  require_same_norms(entry, closed_form);
  require_same_norms(entry, hand);
  const double expected = energy_reference_l2(problem);
  BOOST_TEST(std::abs(entry.levels.back().norms[1].reference_l2 - expected) < 1e-14 * expected);
  const double energy = midpoint_energy_error(problem, 0.0125, 80);
  BOOST_TEST(std::abs(entry.levels.back().norms[1].l2 - energy) < 1e-6 * energy,
             "finest energy error " << entry.levels.back().norms[1].l2 << ", closed form " << energy);
  BOOST_TEST(std::abs(entry.orders[1].fit.value - 3.0) < 0.05, "energy order " << entry.orders[1].fit.value);
}

// CVODE (rtol 1e-12): the entry point and the hand-built study agree bit for bit (the blocks are
// solved independently, so the threads' order does not change a bit), and the finest level's
// norms differ from the closed form's study by no more than the reference's distance from the
// closed form (computed here), itself below 1e-8.
BOOST_AUTO_TEST_CASE(cvode_reference_measures_a_derived_variable) {
  const OscillatorsWithoutClosedForm problem(40);
  const Oscillators same(40);
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  ReferenceSettings cvode;
  cvode.kind = ReferenceKind::cvode;
  const StudyResult entry = run_study(problem, rk2, plan_of_four_levels(), cvode);
  State reference;
  const StudyResult hand = by_hand(problem, rk2, cvode, &reference);
  require_same_norms(entry, hand);
  const StudyResult closed_form = run_study(same, rk2, plan_of_four_levels());
  require_within_reference_distance(entry, closed_form, reference, same);
  BOOST_TEST(entry.reference.trusted);
  BOOST_TEST(std::abs(entry.orders[1].fit.value - 3.0) < 0.05, "energy order " << entry.orders[1].fit.value);
}

// An integrator (rk4 at Δt = 1e-3): bit for bit with the hand-built study; the finest level's
// norms differ from the closed form's study by no more than the reference's distance from the
// closed form (below 1e-8); the error estimate is Richardson's, (16/15)·‖y_Δt − y_Δt/2‖,
// recomputed here from two solves of the test's own.
BOOST_AUTO_TEST_CASE(integrator_reference_measures_a_derived_variable) {
  const OscillatorsWithoutClosedForm problem(40);
  const Oscillators same(40);
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  ReferenceSettings settings;
  settings.kind = ReferenceKind::integrator;
  settings.integrator = std::make_shared<ExplicitRungeKutta<tableau::rk4>>("rk4");
  settings.dt = 1e-3;
  Reference used;
  const StudyResult entry = run_study(problem, rk2, plan_of_four_levels(), settings, {}, &used);
  State reference;
  const StudyResult hand = by_hand(problem, rk2, settings, &reference);
  require_same_norms(entry, hand);
  const StudyResult closed_form = run_study(same, rk2, plan_of_four_levels());
  require_within_reference_distance(entry, closed_form, reference, same);
  BOOST_TEST(used.kind == "integrator");
  BOOST_TEST(used.state.cols() == 2);  // the measured columns

  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  State coarse = problem.initial_state(), fine = problem.initial_state();
  rk4.advance(problem, coarse, 0.0, 1e-3, 1000);
  rk4.advance(problem, fine, 0.0, 5e-4, 2000);
  coarse = problem.measured(coarse, 1.0);
  fine = problem.measured(fine, 1.0);
  for (int v = 0; v < 2; ++v) {
    const double difference = std::sqrt((coarse.col(v) - fine.col(v)).square().sum());
    const double expected = 16.0 / 15.0 * difference;
    BOOST_TEST(std::abs(entry.reference.error[static_cast<std::size_t>(v)] - expected) < 1e-6 * expected,
               "variable " << v << ": " << entry.reference.error[static_cast<std::size_t>(v)] << " vs " << expected);
  }
  BOOST_TEST(entry.reference.trusted);
}

// A step that does not divide t_end, or no integrator: bad input naming the reference.
BOOST_AUTO_TEST_CASE(integrator_reference_refuses_a_step_that_does_not_divide_t_end) {
  const OscillatorsWithoutClosedForm problem(4);
  ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
  ReferenceSettings settings;
  settings.kind = ReferenceKind::integrator;
  settings.integrator = std::make_shared<ExplicitRungeKutta<tableau::rk4>>("rk4");
  settings.dt = 0.3;
  BOOST_CHECK_THROW(run_study(problem, rk2, plan_of_four_levels(), settings), InputError);
  settings.integrator.reset();
  settings.dt = 1e-3;
  BOOST_CHECK_THROW(run_study(problem, rk2, plan_of_four_levels(), settings), InputError);
}

// A journal resumes only the same study: another reference kind, integrator or step is another
// study, and an exact or CVODE reference keeps the keys journals written before held.
BOOST_AUTO_TEST_CASE(journal_identity_tells_references_apart) {
  const OscillatorsWithoutClosedForm problem(4);
  StudyPlan plan = plan_of_four_levels();
  plan.variables = problem.variables();
  ReferenceSettings cvode, exact, rk4_fine, rk4_coarse, rk2_fine;
  cvode.kind = ReferenceKind::cvode;
  for (ReferenceSettings* s : {&rk4_fine, &rk4_coarse, &rk2_fine}) s->kind = ReferenceKind::integrator;
  rk4_fine.integrator = rk4_coarse.integrator = std::make_shared<ExplicitRungeKutta<tableau::rk4>>("rk4");
  rk2_fine.integrator = std::make_shared<ExplicitRungeKutta<tableau::midpoint>>("rk2");
  rk4_fine.dt = rk2_fine.dt = 5e-4;
  rk4_coarse.dt = 1e-3;
  const auto identity = [&](const ReferenceSettings& s) { return study_identity(problem, plan, s); };
  BOOST_TEST(identity(exact)["reference"] == "exact");
  BOOST_TEST(identity(cvode)["reference"] == "cvode");
  BOOST_TEST(!identity(cvode).contains("reference_integrator"));
  BOOST_TEST(identity(rk4_fine)["reference"] == "integrator");
  BOOST_TEST(identity(rk4_fine) != identity(cvode));
  BOOST_TEST(identity(rk4_fine) != identity(rk4_coarse));
  BOOST_TEST(identity(rk4_fine) != identity(rk2_fine));
  BOOST_TEST(identity(rk4_fine) == identity(rk4_fine));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_reference_value
