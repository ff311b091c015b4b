/// @file
/// A study against a reference of any kind (dlpverify/reference.hpp): the reference is computed
/// once, measured like every level, and its error estimate decides the trust margin; the levels
/// are run at fixed steps or by a runner of the caller's (a level search). The whole study as one
/// request, with its verdict and report, is dlpverify/study_request.hpp, built on this.
#pragma once

#include <functional>
#include <vector>

#include "dlpverify/integrator.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// The study of `integrator` on `problem` against a reference of `settings`: the reference is
/// computed once (compute_reference), measured (Problem::measured at t_end) like every level, and
/// its error estimate decides the trust margin. Every level starts from the problem's initial
/// state. Empty plan.variables: the problem's own; plan.expected_order 0: the integrator's order.
/// `progress` continues a journaled study (StudyProgress); `used`, when given, receives the
/// reference (the tightest one, when the levels asked for tighter ones) with its `state` replaced
/// by the measured columns the levels were compared with.
StudyResult run_study(const Problem& problem, Integrator& integrator, StudyPlan plan, const ReferenceSettings& settings,
                      const StudyProgress& progress = {}, Reference* used = nullptr);

/// What runs the levels of a study against the measured reference state (with its estimated error
/// per variable) through `solve`: run_study(plan, …) for fixed levels, a level search
/// (dlpverify/level_search.hpp) for levels it chooses itself, which may ask `tighten` for a
/// tighter reference (tightened_reference).
using LevelRunner = std::function<StudyResult(const StudyPlan& plan, const State& reference,
                                              const std::vector<double>& reference_error, const Solve& solve,
                                              const TightenReference& tighten)>;
/// As run_study above, with the levels run by `run_levels` (a name of its own: a brace-initialised
/// `progress` argument of run_study would otherwise be ambiguous).
StudyResult run_study_with(const Problem& problem, Integrator& integrator, StudyPlan plan,
                           const ReferenceSettings& settings, const LevelRunner& run_levels, Reference* used = nullptr);

}  // namespace dlpverify
