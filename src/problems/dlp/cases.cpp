#include "problems/dlp/case.hpp"

#include "problems/dlp/diagnostics.hpp"
#include "problems/dlp/exact/burn.hpp"
#include "problems/dlp/exact/drag.hpp"
#include "problems/dlp/exact/drag_heat.hpp"
#include "problems/dlp/exact/gravity.hpp"
#include "problems/dlp/exact/similarity.hpp"
#include "problems/dlp/exact/vertical_drag_gravity.hpp"
#include "dlpverify/errors.hpp"

namespace dlpverify::dlp {

namespace {
// Under these defaults, with the seed cloud (R_out = 100): the outermost particle's drag time is
// 1/(K u_s) = 6.25 ms, so t_end = 10 ms spans 1.6 drag times and the coarsest Δt = 0.5 ms resolves
// it with 12.5 steps per drag time — in the asymptotic range for every fixed-step method here, and
// 5 levels (20 … 320 steps) stay well above the round-off floor even for RK4.
constexpr CaseDefaults kSeedStudy{0.01, 5e-4, 5};
// docs/model.md §4.4 on the seed's z axis: v_t = sqrt(g/K) = 2.48 m/s and tau_c = v_t/g = 0.25 s. Over
// 0.2 s the particles at 1 and 2 m/s rise through their apexes (at 0.10 and 0.17 s) and fall from
// rest, those below fall slower (1, 2 m/s) or faster (3 … 100 m/s) than v_t; the fastest have a
// drag time of 6 ms, which Δt = 1 ms resolves.
constexpr CaseDefaults kVerticalStudy{0.2, 1e-3, 5};
}  // namespace

const std::vector<Case>& all_cases() {
  static const std::vector<Case> cases{
      {"similarity", "vacuum expansion: the similarity solution of docs/model.md §2",
       Terms{}, &exact::similarity, "docs/model.md §4.1: x = x0 + v0 tau, v = v0", kSeedStudy, false,
       &diagnostics::similarity_energy},
      {"gravity", "vacuum expansion under gravity",
       Terms{.gravity = true}, &exact::gravity, "docs/model.md §4.2: v = v0 + g tau, x = x0 + v0 tau + g tau^2/2", kSeedStudy},
      {"drag", "expansion into quiescent air, constant drag coefficient (Kuhl & Grote's case)",
       Terms{.drag = true}, &exact::drag, "docs/model.md §4.3: s = s0/(1 + K s0 tau), x = x0 + i ln(1 + K s0 tau)/K", kSeedStudy},
      {"drag-gravity-vertical", "the cloud's z axis: vertical drag and gravity through every branch of docs/model.md §4.4",
       Terms{.drag = true, .gravity = true}, &exact::vertical_drag_gravity,
       "docs/model.md §4.4: v = v_t tan(phi0 - tau/tau_c) rising, -v_t tanh / coth falling", kVerticalStudy, true,
       &diagnostics::vertical_branches},
      {"drag-heat", "constant drag with heat transfer by the Nu(Re) law",
       Terms{.drag = true, .heat = true}, &exact::drag_heat,
       "docs/model.md §4.5: T = T_a + (T0 - T_a) exp(-Lambda), Lambda in closed form", kSeedStudy},
      {"burn", "burning (d-law) with constant drag and heat transfer; t_end before burn-out",
       Terms{.drag = true, .heat = true, .burning = true}, &exact::burn,
       "docs/model.md §4.6: d = d0 - beta tau, speed and distance via E1 (GSL), Lambda by QAG to 1e-13", kSeedStudy},
      // No closed form below: drag is nonlinear, so drag and gravity do not superpose (the seed's
      // eq. 26 adds them, docs/model.md §9), and C_D(Re), heat and burning couple the equations.
      {"drag-gravity", "3-D motion with constant drag and gravity",
       Terms{.drag = true, .gravity = true}, nullptr, "no closed form off the vertical (docs/model.md §4.4)", kSeedStudy},
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
  throw InputError("case", name, "unknown case (known: " + names + ")");
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

}  // namespace dlpverify::dlp
