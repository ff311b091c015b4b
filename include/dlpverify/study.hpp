/// @file
/// The convergence study: Δt levels, one solve per level, norms against the reference, orders.
///
/// The harness knows neither the physics nor the integrator: it is handed a function that returns
/// the state at t0 + t_end for a given (Δt, steps), and the reference state there.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/norms.hpp"
#include "dlpverify/order.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/solver_statistics.hpp"

namespace dlpverify {

/// Study defaults under which a case's expected order shows.
struct StudyDefaults {
  double t_end = 0.0;  ///< duration after t0 [s]
  double dt = 0.0;     ///< coarsest step [s]
  int levels = 0;      ///< number of Δt levels
};

/// The levels of a convergence study.
struct StudyPlan {
  double t_end = 0.0;      ///< duration after t0
  double coarsest_dt = 0.0;  ///< Δt_0 of level 0
  double ratio = 2.0;      ///< Δt_k = Δt_0 / r^k
  int levels = 0;          ///< number of levels k = 0 … levels − 1
  double expected_order = 0.0;  ///< for the round-off rate-drop rule; 0 when unknown
  std::vector<Variable> variables;  ///< what is measured; empty: the problem's own
  /// Variables expected at another order than expected_order, by name (an invariant such as an
  /// energy converges one order above the method): their rules, error constants and checks use it.
  std::map<std::string, double> expected_order_by_variable{};
  /// The arithmetic the levels are stepped and compared in: its epsilon sets the round-off floor
  /// (extended: dlpverify/extended_study.hpp).
  Precision precision = Precision::double_precision;
};

/// The expected order of variable v of the plan: its own, or expected_order.
double expected_order_of(const StudyPlan& plan, std::size_t v);

/// Refuses an expected order by variable that names no variable of the plan, or is not positive
/// and finite: InputError naming the "expected order" and the variable.
void check_expected_orders(const StudyPlan& plan);

/// Steps of each level, t_end / Δt_k, required to be whole within 1e-9 relative (docs/model.md §6).
/// Throws InputError naming the time step (or the step ratio) and the offending value.
std::vector<long> level_steps(const StudyPlan& plan);

/// The most levels a study runs.
inline constexpr int kMostLevels = 30;

/// Refuses a plan no study can run, before any work: a "duration" or coarsest "time step" that is
/// not positive and finite, a "step ratio" that is not finite and above 1, a number of "levels"
/// outside [fewest_levels, kMostLevels] (a study fits an order to two levels or more; a level
/// search starts from one), and steps that are not whole (level_steps). Throws InputError naming
/// the quantity.
void check_plan(const StudyPlan& plan, int fewest_levels = 2);

/// One level of a study: its step, its cost and its error.
struct LevelResult {
  int level = 0;              ///< k
  double dt = 0.0;            ///< Δt_k = Δt_0 / r^k
  long steps = 0;             ///< t_end / Δt_k
  double wall_seconds = 0.0;  ///< the solve alone, steady clock
  std::vector<ErrorNorms> norms;  ///< one per plan variable
  /// ‖y_{k−1} − y_k‖ per plan variable, the L2 norm of the difference from the level before
  /// (docs/model.md §6, self-convergence); none on level 0.
  std::vector<std::optional<double>> self_difference;
  SolverStatistics solver_statistics;  ///< the integrator's statistics() after the solve
};

/// Whether the reference is accurate enough for the study to measure the integrator.
struct ReferenceTrust {
  bool trusted = true;         ///< every margin ≥ kMinimumReferenceMargin
  std::vector<double> error;   ///< the reference's estimated error per variable (0: a closed form)
  std::vector<double> margin;  ///< finest level's error / reference error (infinite for a closed form)
};

/// A finished convergence study.
struct StudyResult {
  StudyPlan plan;                     ///< as run, with the variables filled in
  std::vector<LevelResult> levels;    ///< one per level, coarsest first
  std::vector<OrderAnalysis> orders;  ///< one per plan variable
  std::vector<SelfConvergence> self_convergence;  ///< one per plan variable, reference-free
  ReferenceTrust reference;           ///< the reference's error and margins
  State finest;                       ///< the finest level's state (for per-particle views)
  /// No reference: level k was measured against level k + 1's state (analyse_states), so a
  /// level's norms are differences between runs, not errors.
  bool against_next_level = false;
};

/// Returns the state at t0 + t_end after `steps` steps of dt; may fill solver statistics.
using Solve = std::function<State(double dt, long steps, SolverStatistics& statistics)>;

/// A reference made tighter for a study whose finer levels came too close to it.
struct TighterReference {
  State state;                         ///< measured at t0 + t_end, like every level
  std::vector<double> error_estimate;  ///< its estimated error per variable
  std::string detail;                  ///< what it now is, in a sentence (CVODE's settings)
};
/// Computes the next tighter reference; nullopt when it can be made no tighter (a closed form, a
/// CVODE reference at kTightestReferenceRtol). The study asks for it without knowing its kind.
using TightenReference = std::function<std::optional<TighterReference>()>;

/// A study that can be stopped between its levels (or runs) and continued later (a journal,
/// docs/cli.md, "The journal and --resume"). The loop stays one-way: it takes the results an
/// earlier run of the same study finished, hands each one it finishes itself to `finished`, and
/// asks `stop` before it starts the next.
/// Where a stoppable study starts and what it reports (see StudyProgress).
template <class Finished>
struct Progress {
  std::vector<Finished> done;                         ///< the first done.size(), taken as they are
  std::function<void(const Finished&)> finished;      ///< after each one this run finishes
  std::function<bool()> stop;                         ///< true: throw StudyStopped instead of starting one
};
/// For run_study, `done` are levels 0 … j−1. Only the last is solved again, for its state (the
/// next level's self-difference and the finest state need it); its norms must come out bit for
/// bit as given, or InputError.
using StudyProgress = Progress<LevelResult>;

/// Thrown when Progress::stop asked the study to end before a level (or run): the first
/// levels_done are finished (those this run finished were handed to `finished`), the rest were
/// not started.
class StudyStopped : public std::runtime_error {
 public:
  /// what(): "study stopped after <levels_done> levels".
  explicit StudyStopped(int levels_done)
      : std::runtime_error("study stopped after " + std::to_string(levels_done) + " levels"),
        levels_done_(levels_done) {}
  int levels_done() const { return levels_done_; }  ///< levels finished, 0 … plan.levels − 1

 private:
  int levels_done_;
};

/// Level k measured: the norms of `state` (after `steps` steps of Δt_k = plan.t_end / steps) against
/// `reference` for every plan variable, and ‖y_{k−1} − y_k‖ against `previous`, the state of the
/// level before (none when `previous` is null). The wall time and solver statistics stay empty.
/// The one place a level's numbers come from, for a study that solves its levels (run_study) and
/// for states computed elsewhere (`dlpverify analyze`).
LevelResult measure_level(const StudyPlan& plan, int k, long steps, const State& state, const State& reference,
                          const State* previous);

/// Orders, self-convergence and the reference's trust of `result.levels` (docs/model.md §6), with
/// `reference_error` the reference's estimated error per plan variable (zeros: a closed form).
void analyse_levels(StudyResult& result, const std::vector<double>& reference_error);

/// Level k of `plan` at `steps` steps: solved by `solve`, timed, measured against `reference`, with
/// its self-difference from `previous`, the state of level k − 1 (none when null). Leaves the
/// level's measured state in `state`. The one level of run_study, for loops that add levels one by
/// one (dlpverify/level_search.hpp).
LevelResult run_level(const StudyPlan& plan, int k, long steps, const State& reference, const Solve& solve,
                      const State* previous, State& state);

/// The study of finished `levels` (levels 0 … n − 1 of `plan`, coarsest first): orders,
/// self-convergence and the reference's trust (reference_error per plan variable); `finest` is the
/// finest level's measured state.
StudyResult analyse_study(const StudyPlan& plan, std::vector<LevelResult> levels,
                          const std::vector<double>& reference_error, State finest);

/// reference_error: the reference's estimated error per plan variable (zeros for a closed form).
StudyResult run_study(const StudyPlan& plan, const State& reference, const std::vector<double>& reference_error,
                      const Solve& solve, const StudyProgress& progress = {});

/// A study of states computed elsewhere (`dlpverify analyze`): `states[k]` is level k's measured
/// state at t0 + plan.t_end after level_steps(plan)[k] steps, coarsest first (plan.levels =
/// states.size()). With a `reference` every level is measured against it (`reference_error`: its
/// estimated error per variable, zeros when unknown); without one level k is measured against
/// level k + 1, ‖y_k − y_{k+1}‖ ∝ Δt_k^p as the error is, so the result has one level fewer and the
/// finest state serves only as the last reference (StudyResult::against_next_level); the
/// self-convergence then covers every state, its Richardson estimate and GCI the finest one's.
/// Throws InputError when plan's steps are not whole (level_steps) or states.size() differs.
StudyResult analyse_states(StudyPlan plan, const std::vector<State>& states, const State* reference,
                           const std::vector<double>& reference_error);

class Integrator;
/// The study of `integrator` on `problem` against the problem's closed form at t0 + plan.t_end:
/// every level starts from the problem's initial state. Empty plan.variables: the problem's own.
/// Throws InputError when the problem has no closed form (a CVODE reference is in
/// dlpverify/reference.hpp).
StudyResult run_study(const Problem& problem, Integrator& integrator, StudyPlan plan);

}  // namespace dlpverify
