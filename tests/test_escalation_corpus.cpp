// Decisiveness with and without escalation (docs/verification.md, "Escalation"), measured through
// run(StudyRequest) as a user calls it: every ARKODE explicit table stepped as a tableau file
// would be (TableauIntegrator, from the coefficients ARKODE holds), each with two slipped twins —
// a b_i pair moved by ±1e-3 keeping Σb = 1 (Σ b_i c_i = 1/2 broken: order 1) and, for P ≥ 3, an
// a_ij pair moved by 1e-3 keeping its row sum (Σ b_i a_ij c_j = 1/6 broken: order 2) — on the
// drag and drag-heat cases at R_out 2 and their default levels, against their closed forms.
// A correct method must never fail and a slipped one never pass, with escalation or without; the
// whole matrix is the one recorded in docs/verification.md ("Escalation").
#include <boost/test/unit_test.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "dlpverify/dlp.hpp"
#include "dlpverify/study_request.hpp"
#include "integrators/sundials/arkode_erk_integrator.hpp"
#include "integrators/tableau/tableau_integrator.hpp"

namespace unit_escalation_corpus {

using namespace dlpverify;

namespace {

struct Method {
  RuntimeTableau tableau;
  bool slipped = false;
};

RuntimeTableau tableau_of(const ArkodeTableInfo& info) {
  const ButcherCoefficients k = ArkodeErkIntegrator(info.name).butcher();
  RuntimeTableau t;
  t.name = t.source = info.name;
  t.order = info.order;
  t.a = k.a;
  t.b = k.b;
  t.c = k.c;
  return t;
}

// The correct method and its twins: b_1 and the last b_j with c_j ≠ 0 moved by ∓1e-3; a_i1 and
// a_i,i−1 moved by ±1e-3 in the last row i ≥ 2 with b_i ≠ 0 and c_{i−1} ≠ 0.
std::vector<Method> methods_of(const RuntimeTableau& correct) {
  std::vector<Method> methods{{correct, false}};
  const int s = correct.stages();
  for (int j = s - 1; j > 0; --j)
    if (correct.c[j] != 0.0) {
      Method twin{correct, true};
      twin.tableau.b[0] -= 1e-3;
      twin.tableau.b[j] += 1e-3;
      twin.tableau.name += " (b slipped)";
      methods.push_back(twin);
      break;
    }
  if (correct.order >= 3)
    for (int i = s - 1; i >= 2; --i)
      if (correct.b[i] != 0.0 && correct.c[i - 1] != 0.0) {
        Method twin{correct, true};
        twin.tableau.a[i][0] += 1e-3;
        twin.tableau.a[i][i - 1] -= 1e-3;
        twin.tableau.name += " (a slipped)";
        methods.push_back(twin);
        break;
      }
  return methods;
}

// [correct, slipped][pass, inconclusive, fail]
using Matrix = std::array<std::array<int, 3>, 2>;

int column(const CheckVerdict& verdict) {
  const FindingResult r = verdict.worst();
  return r == FindingResult::pass ? 0 : r == FindingResult::inconclusive ? 1 : 2;
}

std::string shown(const Matrix& m) {
  char text[160];
  std::snprintf(text, sizeof text, "correct %d/%d/%d, slipped %d/%d/%d", m[0][0], m[0][1], m[0][2], m[1][0], m[1][1],
                m[1][2]);
  return text;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(escalation_corpus)

BOOST_AUTO_TEST_CASE(no_correct_method_fails_no_slipped_one_passes) {
  Matrix single{}, escalated{};
  double seconds_single = 0.0, seconds_escalated = 0.0;
  for (const std::string case_name : {"drag", "drag-heat"}) {
    const std::unique_ptr<Problem> problem = dlp::make_problem(case_name, {.outer = 2});
    const StudyDefaults defaults = dlp::case_defaults(case_name);
    for (const ArkodeTableInfo& info : arkode_erk_tables())
      for (const Method& method : methods_of(tableau_of(info))) {
        StudyRequest request;
        request.problem = problem.get();
        request.make_integrator = [&method](const Problem&) { return std::make_unique<TableauIntegrator>(method.tableau); };
        request.plan = {defaults.t_end, defaults.dt, 2.0, defaults.levels, double(method.tableau.order), {}};
        request.reference.kind = ReferenceKind::exact;
        request.check.emplace();
        request.check->order = method.tableau.order;
        for (const bool escalate : {false, true}) {
          request.escalate = escalate;
          const auto start = std::chrono::steady_clock::now();
          const StudyOutcome outcome = run(request);
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const int c = column(*outcome.verdict);
          (escalate ? escalated : single)[method.slipped][c] += 1;
          (escalate ? seconds_escalated : seconds_single) += seconds;
          BOOST_TEST_CONTEXT(case_name << " " << method.tableau.name << (escalate ? " escalated" : " single")) {
            BOOST_TEST(!(method.slipped ? c == 0 : c == 2), outcome.verdict->lines().front());
            if (escalate && c == 1) BOOST_TEST_MESSAGE("inconclusive: " << outcome.table.substr(0, outcome.table.find("\n\n")));
          }
        }
      }
  }
  // Measured: escalation settles 5 of the 9 correct studies double leaves undecided (extended
  // precision) and the 4 slipped ones (finer levels in double: all fail); the 4 correct ones left
  // are ARK5(4)8L[2]SA's (coefficients no small fraction holds) and ARK4(3)7L[2]SA's velocity,
  // above the band at 9 levels as at 5, on either case.
  const Matrix single_measured{{{21, 9, 0}, {0, 4, 54}}}, escalated_measured{{{26, 4, 0}, {0, 0, 58}}};
  BOOST_TEST(shown(single) == shown(single_measured));
  BOOST_TEST(shown(escalated) == shown(escalated_measured));
  BOOST_TEST_MESSAGE("single pass: " << shown(single) << " in " << seconds_single << " s; escalated: "
                                     << shown(escalated) << " in " << seconds_escalated << " s");
  std::printf("escalation corpus: single pass %s in %.1f s; escalated %s in %.1f s\n", shown(single).c_str(),
              seconds_single, shown(escalated).c_str(), seconds_escalated);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_escalation_corpus
