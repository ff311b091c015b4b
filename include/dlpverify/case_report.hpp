/// @file
/// What a problem reports besides its errors: its physical parameters (for provenance and for a
/// program outside dlpverify), its diagnostics (branch counts, invariants) and the unit of its time. A capability
/// (problem.hpp) the reports and the exchange use; without it both are empty.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// A problem's parameters and diagnostics, as JSON objects for the reports.
class CaseReport : public Capability {
 public:
  /// Physical parameters for provenance: names to SI numbers, or to words for settings.
  virtual nlohmann::json parameters() const = 0;
  /// What the case reports besides errors, from the initial state and the finest level's state at
  /// t0 + t_end of the members they hold.
  virtual nlohmann::json diagnostics(const State& initial, const State& finest, double t_end) const = 0;
};

/// The unit of a problem's time (of t0, t_end and every Δt), for the reports and the figures'
/// axes. Without it a problem's time is in seconds.
class TimeUnit : public Capability {
 public:
  /// "s", "1" when dimensionless, or any unit the problem's time is in.
  virtual std::string time_unit() const = 0;
};

/// CaseReport::parameters of `problem`, or an empty object.
nlohmann::json case_parameters(const Problem& problem);
/// CaseReport::diagnostics of `problem`, or an empty object.
nlohmann::json case_diagnostics(const Problem& problem, const State& initial, const State& finest, double t_end);

}  // namespace dlpverify
