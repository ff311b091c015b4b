// The verdict of Zohdi's Algorithm 7.1 on a coupled system or the cooling particles
// (docs/cooling.md, `stagger --adaptive`): every accepted step below the staggered iteration's
// convergence limit (the coupled systems' √(ab) or |abc|^{1/4}), and, with error control, the
// error at the end within 10 × TOL of the closed form.
#pragma once

#include "dlpverify/problem.hpp"
#include "integrators/implicit/adaptive.hpp"

namespace dlpverify::thermal {

struct AdaptiveVerdict {
  double error = 0.0;  // max over members of ‖y − y_exact‖/‖y_exact‖ at the end; NaN without a closed form
  double limit = 0.0;  // the step limit; NaN for a problem without one
  bool below_limit = true;
  bool accurate = true;  // error ≤ 10 × tolerance, or not controlled, or no closed form
  bool passed() const { return below_limit && accurate; }
};

// `run` from `initial` over `duration` at the local-error tolerance `tolerance`; `error_control`
// false: the error is reported, not judged.
AdaptiveVerdict check_adaptive(const Problem& problem, const implicit::AdaptiveRun& run, const State& initial,
                               double duration, double tolerance, bool error_control);

}  // namespace dlpverify::thermal
