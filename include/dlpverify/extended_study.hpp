/// @file
/// A convergence study in extended precision (StudyPlan::precision = extended): every level
/// stepped in Extended by the integrator's own Butcher tableau (dlpverify/extended_runge_kutta.hpp),
/// measured against the extended reference (ReferenceKind::extended) with each difference taken in
/// Extended, and its orders judged above Extended's round-off floor (ε = 2^−104). A method's
/// asymptotic range that double's floor of ~1e-14 hides — a fifth-order method's, or a fourth
/// order one's at fine steps — is then measured. The numbers reported are doubles.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dlpverify/integrator.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

class ExtendedState;
/// measure_level (dlpverify/study.hpp) for states in Extended: each difference is taken in
/// Extended and rounded once (error_norms), the one place an extended level's numbers come from.
LevelResult measure_level(const StudyPlan& plan, int k, long steps, const ExtendedState& state,
                          const ExtendedState& reference, const ExtendedState* previous);

/// Steps the problem's initial state `steps` times in Extended to t0 + t_end (Δt = t_end / steps
/// in Extended), setting `statistics`.
using ExtendedSolve = std::function<ExtendedState(long steps, SolverStatistics& statistics)>;

/// run_study (dlpverify/study.hpp) for levels solved in Extended: the same loop, the same
/// journal of levels (`progress`: those finished taken over, the last solved again and its norms
/// compared bit for bit, each new one handed on), each level measured in Extended.
StudyResult run_study(const StudyPlan& plan, const ExtendedState& reference, const std::vector<double>& reference_error,
                      const ExtendedSolve& solve, const StudyProgress& progress = {});

/// Why `integrator` on `problem` cannot be stepped in Extended, in the words of a refusal naming the
/// "precision"; empty when it can: the integrator is a Butcher tableau the tool steps itself
/// (ButcherMethod) and the problem offers ExtendedRhs. The one rule of what runs in extended
/// precision, for run_extended_study and an escalation (StudyRequest::escalate).
std::string extended_refusal(const Problem& problem, const Integrator& integrator);

/// The study of `integrator` on `problem` at plan's fixed levels in Extended, its levels through
/// `progress` as run_study's. Refuses, with
/// InputError naming the "precision", an integrator that is not a Butcher tableau the tool steps
/// itself (ButcherMethod: the built-in Runge–Kutta methods and explicit tableau files), a problem
/// without ExtendedRhs, and a reference of any kind but extended (a double reference would be the
/// study's floor). `used`, when given, receives the reference.
StudyResult run_extended_study(const Problem& problem, const Integrator& integrator, StudyPlan plan,
                               const ReferenceSettings& settings, const StudyProgress& progress = {},
                               Reference* used = nullptr);

}  // namespace dlpverify
