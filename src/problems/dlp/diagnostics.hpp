// Case diagnostics: what a case reports besides its errors.
#pragma once

#include "problems/dlp/case.hpp"

namespace dlpverify::dlp::diagnostics {

// similarity (docs/model.md §2): the kinetic energy Σ ½ m v² at launch and at the end of the finest
// level (constant to round-off in vacuum), and its ratio to the continuous sphere's 0.3 M u_s².
nlohmann::json similarity_energy(const DiagnosticsInput& input);

// drag-gravity-vertical (docs/model.md §4.4): how many particles take each branch over [0, t_end].
nlohmann::json vertical_branches(const DiagnosticsInput& input);

}  // namespace dlpverify::dlp::diagnostics
