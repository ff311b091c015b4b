// The staggering studies of `dlpverify stagger` (docs/cooling.md, docs/model.md §7.3), each with
// its console text, JSON and CSV: the contraction per sweep of one backward-Euler step's staggered
// iteration at each step, beside the coupled system's spectral radius; and Zohdi's Algorithm 7.1
// over a duration, judged by check_adaptive.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/problem.hpp"
#include "integrators/implicit/adaptive.hpp"

namespace dlpverify::thermal {

struct StaggeringReport {
  std::string text;       // the console table
  nlohmann::json result;  // the JSON (the caller adds provenance and options)
  std::string csv;        // the rows (contraction) or the counts (adaptive)
  bool passed = true;     // adaptive: every accepted step below the limit and the error within bounds
  // Contraction: the first step whose iteration did not converge, and what it did ("the staggered
  // iteration diverges after 4 sweeps: …"); a failed study has no results.
  std::optional<double> failed_step;
  std::string failure;
};

// One backward-Euler step from the problem's initial state at each of `steps`, swept to round-off.
StaggeringReport contraction_study(const Problem& problem, implicit::Sweep sweep, const std::vector<double>& steps);

struct AdaptiveStudy {
  implicit::AdaptiveSettings settings;
  double first_step = 0.0;
  double duration = 0.0;
  double tolerance = 0.0;     // TOL, and 10 × TOL the bound on the error at the end
  bool error_control = true;  // false: the document's control alone, the error reported, not judged
};

// Algorithm 7.1 from the problem's initial state over study.duration.
StaggeringReport adaptive_study(const Problem& problem, const AdaptiveStudy& study);

}  // namespace dlpverify::thermal
