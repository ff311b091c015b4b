// The CVODE reference (dlpverify/reference.hpp) is as good as it claims: at its default rtol 1e-12
// it meets the drag closed form — written out here, independently of src/problems/dlp/exact — to
// 1e-10 relative, and its own error estimate (a second solve at rtol/10) is not an
// underestimate. A reference looser than it claims would make every CVODE-reference study
// measure the reference instead of the integrator, with every test still green.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "dlpverify/dlp.hpp"
#include "dlpverify/norms.hpp"
#include "dlpverify/reference.hpp"

namespace unit_cvode_reference {

using namespace dlpverify;

namespace {

// docs/model.md §4.3, drag only, constant C_D, quiescent gas: dv/dt = −K ‖v‖ v with
// K = 3 ρ_a C_D / (4 ρ_p d0) = 3 · 1.2 · 0.48 / (4 · 2700 · 1e-4) = 1.6 m⁻¹. The direction is kept
// and the speed obeys ds/dt = −K s², so s = s0 / (1 + K s0 τ), v = v0 / (1 + K s0 τ), and
// x = x0 + (v0 / s0) ln(1 + K s0 τ) / K. Fields: x, y, z, vx, vy, vz, T, m (T and m constant).
State drag_by_hand(const State& initial, double tau) {
  constexpr double K = 1.6;
  State y = initial;
  for (Eigen::Index p = 0; p < initial.rows(); ++p) {
    const double s0 = std::sqrt(initial(p, 3) * initial(p, 3) + initial(p, 4) * initial(p, 4) + initial(p, 5) * initial(p, 5));
    const double growth = 1.0 + K * s0 * tau;
    for (int i = 0; i < 3; ++i) {
      y(p, 3 + i) = initial(p, 3 + i) / growth;
      if (s0 > 0.0) y(p, i) = initial(p, i) + initial(p, 3 + i) / s0 * std::log(growth) / K;
    }
  }
  return y;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cvode_reference)

// The drag case on R_out 10 (4,169 particles, 5 blocks of 1024) over its default 0.01 s.
BOOST_AUTO_TEST_CASE(rtol_1e12_meets_the_drag_closed_form_to_1e10) {
  const auto drag = dlp::make_problem("drag", {.outer = 10});
  const State initial = drag->initial_state();
  const double t_end = dlp::case_defaults("drag").t_end;
  ReferenceSettings settings;
  settings.kind = ReferenceKind::cvode;
  BOOST_TEST(settings.rtol == 1e-12);  // the default every CVODE-reference study uses
  const std::vector<Variable> variables = drag->variables();
  const Reference reference = compute_reference(*drag, settings, initial, t_end, variables);
  const State exact = drag_by_hand(initial, t_end);
  for (std::size_t v = 0; v < variables.size(); ++v) {
    const ErrorNorms norms = error_norms(reference.state, exact, variables[v]);
    BOOST_TEST_MESSAGE(variables[v].name << ": relative L2 distance from the closed form " << norms.relative
                                         << ", estimated error " << reference.error_estimate[v]
                                         << ", actual " << norms.l2);
    BOOST_TEST(norms.relative <= 1e-10, variables[v].name << ": " << norms.relative);
    // The estimate may be pessimistic, never optimistic by more than a factor 10.
    BOOST_TEST(norms.l2 <= 10.0 * reference.error_estimate[v], variables[v].name);
  }
}

// tightened_reference (docs/verification.md, "Levels found by the study"): CVODE at rtol/100 down
// to the floor 1e-14, an integrator at Δt / the ratio, a closed form never.
BOOST_AUTO_TEST_CASE(tightened_reference_divides_rtol_by_100_down_to_the_floor) {
  ReferenceSettings cvode;
  cvode.kind = ReferenceKind::cvode;
  cvode.rtol = 1e-10;
  BOOST_CHECK_CLOSE(tightened_reference(cvode, 2.0)->rtol, 1e-12, 1e-9);
  cvode.rtol = 1e-13;
  BOOST_CHECK_EQUAL(tightened_reference(cvode, 2.0)->rtol, kTightestReferenceRtol);
  cvode.rtol = kTightestReferenceRtol;
  BOOST_CHECK(!tightened_reference(cvode, 2.0));

  ReferenceSettings integrator;
  integrator.kind = ReferenceKind::integrator;
  integrator.dt = 1e-4;
  BOOST_CHECK_CLOSE(tightened_reference(integrator, 2.0)->dt, 5e-5, 1e-12);
  BOOST_CHECK(!tightened_reference(integrator, 1.5));  // Δt/1.5 need not divide t_end

  ReferenceSettings exact;
  BOOST_CHECK(!tightened_reference(exact, 2.0));
  exact.kind = ReferenceKind::manufactured;
  BOOST_CHECK(!tightened_reference(exact, 2.0));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_cvode_reference
