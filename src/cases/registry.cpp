#include "cases/case.hpp"

#include "exact/drag.hpp"
#include "exact/gravity.hpp"
#include "exact/similarity.hpp"
#include "io/errors.hpp"

namespace dlpverify {

namespace {
// Under these defaults, with the seed cloud (R_out = 100): the outermost particle's drag time is
// 1/(K u_s) = 6.25 ms, so t_end = 10 ms spans 1.6 drag times and the coarsest Δt = 0.5 ms resolves
// it with 12.5 steps per drag time — in the asymptotic range for every fixed-step method here, and
// 5 levels (20 … 320 steps) stay well above the round-off floor even for RK4.
constexpr CaseDefaults kSeedStudy{0.01, 5e-4, 5};
}  // namespace

const std::vector<Case>& all_cases() {
  static const std::vector<Case> cases{
      {"similarity", "vacuum expansion: the similarity solution of SPEC §2",
       Terms{}, &exact::similarity, "SPEC 4.1: x = x0 + v0 tau, v = v0", kSeedStudy},
      {"gravity", "vacuum expansion under gravity",
       Terms{.gravity = true}, &exact::gravity, "SPEC 4.2: v = v0 + g tau, x = x0 + v0 tau + g tau^2/2", kSeedStudy},
      {"drag", "expansion into quiescent air, constant drag coefficient (the seed's case)",
       Terms{.drag = true}, &exact::drag, "SPEC 4.3: s = s0/(1 + K s0 tau), x = x0 + i ln(1 + K s0 tau)/K", kSeedStudy},
      // No closed form below: drag is nonlinear, so drag and gravity do not superpose (the seed's
      // eq. 26 adds them, SPEC §9), and C_D(Re), heat and burning couple the equations.
      {"drag-gravity", "3-D motion with constant drag and gravity",
       Terms{.drag = true, .gravity = true}, nullptr, "no closed form off the vertical (SPEC 4.4)", kSeedStudy},
      {"drag-law", "drag with the C_D(Re) = 0.48 + 28 Re^-0.85 law",
       Terms{.drag = true, .drag_law = DragLaw::reynolds}, nullptr, "no closed form", kSeedStudy},
      {"full", "every term: C_D(Re) drag, gravity, heat transfer (Nu law), burning; t_end before burn-out",
       Terms{.drag = true, .drag_law = DragLaw::reynolds, .gravity = true, .heat = true, .burning = true}, nullptr,
       "no closed form", kSeedStudy},
  };
  return cases;
}

const Case& find_case(const std::string& name) {
  std::string names;
  for (const Case& c : all_cases()) {
    if (c.name == name) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throw InputError("--case", name, "unknown case (known: " + names + ")");
}

std::string describe_terms(const Terms& terms) {
  std::string text;
  auto add = [&](const std::string& term) { text += (text.empty() ? "" : ", ") + term; };
  if (terms.drag) add(terms.drag_law == DragLaw::constant ? "drag (constant C_D)" : "drag (C_D(Re) law)");
  if (terms.gravity) add("gravity");
  if (terms.heat) add("heat transfer (Nu law)");
  if (terms.burning) add("burning");
  return text.empty() ? "none (vacuum)" : text;
}

}  // namespace dlpverify
