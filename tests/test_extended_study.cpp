// Extended precision's study (dlpverify/extended_study.hpp): coefficients read as the fractions
// they print, RK4 stepped in double-double where its error lies below double's round-off floor,
// the extrapolation reference to ε_Extended, and the refusals. Every value is compared with a
// closed form computed here.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "dlpverify/errors.hpp"
#include "dlpverify/extended.hpp"
#include "dlpverify/extended_runge_kutta.hpp"
#include "dlpverify/extended_study.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/study.hpp"

namespace unit_extended_study {

using namespace dlpverify;

namespace {

// y′ = −λ_p y with λ_p = 1 + p/4, y(0) = 1, for four members: closed form e^{−λ_p t}.
class Decay final : public Problem, public ExtendedRhs {
 public:
  Decay() { provide<ExtendedRhs>(*this); }
  std::string name() const override { return "decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  Eigen::Index members() const override { return 4; }
  State initial_state() const override { return State::Ones(4, 1); }
  static double rate(Eigen::Index p) { return 1.0 + static_cast<double>(p) / 4.0; }
  void rhs(double, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = -rate(first + i) * y[0][i];
  }
  void extended_rhs(const Extended&, Eigen::Index first, int count, const Extended* const* y,
                    Extended* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = -rate(first + i) * y[0][i];
  }
};

// The same problem in double only.
class DoubleDecay final : public Problem {
 public:
  std::string name() const override { return "double-decay"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  Eigen::Index members() const override { return 1; }
  State initial_state() const override { return State::Ones(1, 1); }
  void rhs(double, Eigen::Index, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = -y[0][i];
  }
};

// RK4's amplification on y′ = −λy: R(z) = 1 + z + z²/2 + z³/6 + z⁴/24 at z = −λh.
Extended rk4_amplification(const Extended& z) { return 1.0 + z * (1.0 + z * (0.5 + z * (Extended(1.0) / 6.0 + z / 24.0))); }

// RK4 in extended on Decay over t ∈ [0, 1], `levels` levels from `coarsest_steps` steps, against
// the extended reference.
StudyResult rk4_extended_study(long coarsest_steps, int levels) {
  const Decay problem;
  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 1.0 / static_cast<double>(coarsest_steps);
  plan.levels = levels;
  plan.precision = Precision::extended;
  ReferenceSettings settings;
  settings.kind = ReferenceKind::extended;
  return run_extended_study(problem, rk4, plan, settings);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(extended_study)

// 1/3, 2/9 and 7/24 as a tableau file prints them to 16 digits are read back as the fractions;
// √2 has no fraction of denominator ≤ 2^24 whose nearest double it is, and is kept as written.
BOOST_AUTO_TEST_CASE(coefficients_are_the_fractions_their_doubles_print) {
  BOOST_TEST((exact_coefficient(0.3333333333333333) == Extended(1.0) / 3.0));
  BOOST_TEST((exact_coefficient(0.2222222222222222) == Extended(2.0) / 9.0));
  BOOST_TEST((exact_coefficient(0.2916666666666667) == Extended(7.0) / 24.0));
  BOOST_TEST((exact_coefficient(-0.75) == Extended(-0.75)));
  BOOST_TEST((exact_coefficient(std::sqrt(2.0)) == Extended(std::sqrt(2.0))));
  BOOST_TEST((exact_coefficient(1.0 / 3.0 + 0x1p-52) == Extended(1.0 / 3.0 + 0x1p-52)));  // not 1/3's double
}

// After N steps of RK4 the solution is R(−λh)^N exactly: the stepper's error against e^{−λ} is the
// closed form's to 1e-10 relative, at 1e-17 — where double's floor ½ε√N ≈ 7e-15 hides it.
BOOST_AUTO_TEST_CASE(rk4_in_extended_is_its_amplification_to_the_last_digits) {
  const Decay problem;
  const ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  const ExtendedRungeKutta method(rk4.butcher());
  const long steps = 4096;
  ExtendedState state(problem.initial_state());
  method.advance(problem, state, Extended(0.0), Extended(1.0) / static_cast<double>(steps), steps);
  for (Eigen::Index p = 0; p < 4; ++p) {
    const Extended z = -Decay::rate(p) / Extended(static_cast<double>(steps));
    const Extended expected = pow(rk4_amplification(z), static_cast<int>(steps));
    const double error = to_double(state(p, 0) - exp(Extended(-Decay::rate(p))));
    BOOST_TEST(std::abs(to_double(state(p, 0) - expected)) <= 1e-10 * std::abs(error));
    BOOST_TEST(std::abs(error) < 1e-16);
    BOOST_TEST(std::abs(error) > 1e-19);
  }
}

// The extrapolation reference reaches e^{−λ} to 1e-30 and says its own error is that small.
BOOST_AUTO_TEST_CASE(the_extended_reference_is_the_closed_form_to_1e_30) {
  const Decay problem;
  ReferenceSettings settings;
  settings.kind = ReferenceKind::extended;
  const Reference reference = compute_reference(problem, settings, problem.initial_state(), 2.0, problem.variables());
  BOOST_REQUIRE(reference.extended);
  for (Eigen::Index p = 0; p < 4; ++p)
    BOOST_TEST(std::abs(to_double((*reference.extended)(p, 0) - exp(Extended(-2.0 * Decay::rate(p))))) < 1e-30);
  BOOST_TEST(reference.error_estimate.at(0) < 1e-29);
  BOOST_TEST(reference.kind == "extended");
  BOOST_TEST(reference.state(3, 0) == std::exp(-3.5), boost::test_tools::tolerance(1e-15));  // λ_3 t = 1.75 · 2
}

// RK4 at 2^10 … 2^13 steps: in double the finest levels are round-off; in extended every level
// converges at 4.00 and the finest error, ~1e-17, is measured.
BOOST_AUTO_TEST_CASE(a_study_in_extended_measures_below_doubles_floor) {
  const StudyResult study = rk4_extended_study(1024, 4);
  BOOST_REQUIRE(study.levels.size() == 4u);
  BOOST_TEST(study.levels.back().norms[0].l2 < 1e-16);
  for (LevelStatus status : study.orders[0].status) BOOST_TEST((status == LevelStatus::ok));
  BOOST_TEST(study.orders[0].fit.value == 4.0, boost::test_tools::tolerance(2e-3));
  // The floor the levels are judged by is Extended's: ½ · 2^−104 · √steps · ‖y‖.
  BOOST_TEST(study.orders[0].floor.back() < 1e-28);
}

// RK4 at 2^14 … 2^16 steps, where double's round-off floor is ½ ε √steps ‖y‖ ≈ 3e-15 … 1e-14
// (levels of errors ~1e-20 and below would be round-off in double): in extended each level's error
// is the one the closed form gives, √(Σ_p (R(−λ_p h)^N − e^{−λ_p})²) with R RK4's amplification,
// the finest below 1e-20, and the orders 4.
BOOST_AUTO_TEST_CASE(an_error_below_1e_20_is_measured_as_the_closed_form_gives_it) {
  const StudyResult study = rk4_extended_study(16384, 3);
  BOOST_REQUIRE(study.levels.size() == 3u);
  for (int k = 0; k < 3; ++k) {
    const int doublings = 14 + k;  // N = 2^doublings steps of h = 1/N
    Extended sum = 0.0;
    for (Eigen::Index p = 0; p < 4; ++p) {
      const Extended lambda = Decay::rate(p);
      Extended amplified = rk4_amplification(-lambda / std::ldexp(1.0, doublings));
      for (int d = 0; d < doublings; ++d) amplified = amplified * amplified;  // R^N by squaring
      const Extended error = amplified - exp(-lambda);
      sum += error * error;
    }
    BOOST_TEST(study.levels[static_cast<std::size_t>(k)].norms[0].l2 == to_double(sqrt(sum)),
               boost::test_tools::tolerance(1e-6));
  }
  BOOST_TEST(study.levels.back().norms[0].l2 < 1e-20);
  BOOST_TEST(study.levels.back().norms[0].l2 > 1e-23);  // measured, not round-off: ~1.5e-21
  for (LevelStatus status : study.orders[0].status) BOOST_TEST((status == LevelStatus::ok));
  BOOST_TEST(study.orders[0].fit.value == 4.0, boost::test_tools::tolerance(1e-3));
}

// A study in extended resumed from the first two of its four levels (a journal's, as a signal
// leaves them) gives the uninterrupted study's numbers bit for bit; the last level taken over is
// solved again, and a level whose norms differ from that solve is refused.
BOOST_AUTO_TEST_CASE(an_extended_study_resumes_from_its_finished_levels) {
  const Decay problem;
  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 1.0 / 64.0;
  plan.levels = 4;
  plan.precision = Precision::extended;
  ReferenceSettings settings;
  settings.kind = ReferenceKind::extended;
  std::vector<LevelResult> finished;
  StudyProgress first;
  first.finished = [&finished](const LevelResult& level) { finished.push_back(level); };
  const StudyResult whole = run_extended_study(problem, rk4, plan, settings, first);
  BOOST_REQUIRE(finished.size() == 4u);
  StudyProgress resumed;
  resumed.done.assign(finished.begin(), finished.begin() + 2);
  int solved = 0;
  resumed.finished = [&solved](const LevelResult&) { ++solved; };
  const StudyResult again = run_extended_study(problem, rk4, plan, settings, resumed);
  BOOST_TEST(solved == 2);  // levels 2 and 3
  for (int k = 0; k < 4; ++k) {
    BOOST_TEST(again.levels[k].norms[0].l2 == whole.levels[k].norms[0].l2);
    BOOST_TEST(again.levels[k].self_difference[0].value_or(-1.0) == whole.levels[k].self_difference[0].value_or(-1.0));
  }
  BOOST_TEST(again.finest(0, 0) == whole.finest(0, 0));
  resumed.done[1].norms[0].l2 *= 1.0 + 1e-15;
  BOOST_CHECK_THROW(run_extended_study(problem, rk4, plan, settings, resumed), InputError);
}

BOOST_AUTO_TEST_CASE(what_extended_cannot_step_is_refused_by_name) {
  StudyPlan plan;
  plan.t_end = 1.0;
  plan.coarsest_dt = 0.1;
  plan.levels = 2;
  plan.precision = Precision::extended;
  ReferenceSettings extended;
  extended.kind = ReferenceKind::extended;
  ExplicitRungeKutta<tableau::rk4> rk4("rk4");
  const auto names = [](const char* quantity) {
    return [quantity](const InputError& e) { return e.quantity() == quantity; };
  };
  BOOST_CHECK_EXCEPTION(run_extended_study(DoubleDecay(), rk4, plan, extended), InputError, names("precision"));
  ReferenceSettings cvode;
  cvode.kind = ReferenceKind::cvode;
  BOOST_CHECK_EXCEPTION(run_extended_study(Decay(), rk4, plan, cvode), InputError, names("reference"));
  ButcherCoefficients implicit_euler{{{1.0}}, {1.0}, {1.0}};
  BOOST_CHECK_EXCEPTION(ExtendedRungeKutta{implicit_euler}, InputError, names("precision"));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_extended_study
