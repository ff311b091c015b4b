// Case diagnostics: what a case reports besides its errors.
#pragma once

#include "problems/dlp/case.hpp"

namespace dlpverify::dlp::diagnostics {

// similarity (docs/model.md §2): the kinetic energy Σ ½ m v² at launch and at the end of the finest
// level (constant to round-off in vacuum), and its ratio to the continuous sphere's 0.3 M u_s².
extern const CaseDiagnostics similarity_energy;

// drag-gravity-vertical (docs/model.md §4.4): how many particles take each branch over [0, t_end].
extern const CaseDiagnostics vertical_branches;

}  // namespace dlpverify::dlp::diagnostics
