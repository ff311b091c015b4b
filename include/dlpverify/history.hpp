/// @file
/// Error history: the L2 norms of the finest level at regular output times, against the
/// reference at those same times, so error against time can be drawn (issue 5).
///
/// The finest level is re-run in segments between output times. For the fixed-step methods
/// (autonomous right-hand side) the segments reproduce the study's finest level exactly, so the
/// last point equals its error at t_end; a variable-step solver restarts at every output time.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dlpverify/norms.hpp"
#include "dlpverify/problem.hpp"

namespace dlpverify {

/// The error of the finest level at one output time.
struct HistoryPoint {
  double tau;               ///< time since t0
  std::vector<double> l2;   ///< one per measured variable
  std::vector<double> reference_l2;  ///< the reference's own size √Σ‖y‖², for relative plots
};

/// Advances `state` by `steps` steps of dt starting at τ = tau_from.
using AdvanceSteps = std::function<void(State& state, double tau_from, double dt, long steps)>;
/// The reference state at τ; called with increasing τ, so a solver may continue from the last one.
using ReferenceAt = std::function<State(double tau)>;
/// The measured columns of a state at τ (Problem::measured); the norms compare those.
using Measure = std::function<State(const State& state, double tau)>;

/// `outputs` points spaced evenly in whole steps over the finest level's `steps` steps of dt
/// (fewer when there are fewer steps), the last at t_end.
std::vector<HistoryPoint> record_history(const State& initial, const std::vector<Variable>& variables,
                                         double dt, long steps, int outputs, const AdvanceSteps& advance,
                                         const ReferenceAt& reference_at, const Measure& measure = nullptr);

/// CSV `t,l2_<var>…,ref_l2_<var>…` with t the time since t0 in `time_unit` (the problem's,
/// harness/step_unit.hpp), under a units line `# units: <t's unit>,<each column's unit>` when some
/// unit is not the one a reader assumes without it (t in s, the built-in variables' SI units).
std::string format_history(const std::vector<HistoryPoint>& history, const std::vector<Variable>& variables,
                           const std::string& time_unit = "s");

}  // namespace dlpverify
