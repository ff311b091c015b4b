// The phases of a level search (dlpverify/level_search.hpp): each reads the search so far and
// returns a Decision — go on refining, start over (coarser, or against a tighter reference), or
// stop with its kind and reason. Only search_levels turns a decision into the search's stop and
// reason; the phases keep the levels, states and the record of what was run.
#pragma once

#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "dlpverify/level_search.hpp"

namespace dlpverify::search_phase {

// What a phase decided.
struct Decision {
  enum class Kind { go_on, start_over, stop };
  Kind kind = Kind::go_on;
  SearchStop stop = SearchStop::order_interval;  // with Kind::stop
  std::string reason;                            // with Kind::stop: the stop in a sentence

  static Decision go_on() { return {}; }
  static Decision start_over() { return {Kind::start_over, SearchStop::order_interval, {}}; }
  static Decision stop_at(SearchStop stop, std::string reason) { return {Kind::stop, stop, std::move(reason)}; }
  bool decided() const { return kind != Kind::go_on; }
};

// The search so far: the levels kept and the last two states (a level left out for the
// reference's accuracy hands the finest state back to the level before it), the reference they are
// measured against, and the record of every level run.
struct Search {
  Search(const LevelSearchRules& search_rules, LevelSearch& search_record, StudyPlan start)
      : rules(search_rules), record(search_record), plan(std::move(start)) {}
  const LevelSearchRules& rules;
  LevelSearch& record;                                    // run, tightenings, settled: never stop nor reason
  StudyPlan plan;
  const State* reference = nullptr;                       // the reference the levels are measured against …
  const std::vector<double>* reference_error = nullptr;   // … and its estimated error
  std::optional<TighterReference> tighter;                // the tightest reference asked for, if any
  std::vector<LevelResult> levels;
  int settled_in_a_row = 0;            // levels in a row at which every variable settled
  int failed_in_a_row = 0;             // levels in a row at which the check's verdict was fail
  int coarsenings = 0;                 // starts made coarser so far
  State previous, before_previous;
  StudyResult result;                  // the levels kept, analysed
  std::optional<LevelResult> left_out;  // the level left out for the reference's accuracy …
  State left_out_state;                 // … and its state, where refinement by self-differences goes on
};

// Half-width of the fitted order's 95% interval; infinite without an interval.
double half_width(const OrderFit& fit);

// Refine: a further level may start (go_on, its step count in `steps`), or the budget, the level
// limit or whole steps stop the search.
Decision refine(const Search& s, double elapsed, long& steps);

// Coarsen a start too fine: its first level at the round-off floor for every variable (on two
// levels); the search starts over from Δt_0 × r.
Decision coarsen_start(Search& s);
// Coarsen after a stop that left some variable's window short of min_fit_levels while the coarsest
// level is still asymptotic: the search starts over from Δt_0 × r; else the stop stands.
Decision coarsen_short_window(Search& s, Decision stop);

// Tighten the reference when the newest level comes within kMinimumReferenceMargin of its
// estimated error and `tighten` gives a tighter one: the levels are solved again (start over).
Decision tighten_reference(Search& s, const TightenReference& tighten);
// Stop on the reference's accuracy when the newest level comes within kMinimumReferenceMargin of
// its estimated error (the reference at its tightest): the level is left out while two stay.
Decision reference_accuracy(Search& s);

// Settle: every variable settled by its interval (confirmed at one more level) or by the round-off
// floor stops the search; the settling notes go to the record.
Decision settle(Search& s);
// Decided: a check's verdict of fail at two levels in a row, over windows of min_fit_levels or
// more, stops the search (finer levels of a method that misses its order only confirm it).
Decision decided(Search& s, const FailsCheck& fails);
// Per variable: how it was settled, or why not (the record's `settled`).
std::vector<std::string> settling_notes(const Search& s);

// The order of each variable the search could not settle (not exact, interval not narrow),
// extrapolated from its pairwise orders over the kept levels, which the reference trusts.
std::vector<std::optional<OrderExtrapolation>> extrapolate_unsettled(const StudyResult& result,
                                                                     const LevelSearchRules& rules);

// After a stop on the reference's accuracy with the reference at its tightest: refines on from the
// level left out, measuring the differences between successive levels (no reference needed), for
// the variables whose extrapolation was refused for want of pairwise orders; their extrapolations
// are replaced in `extrapolations`. Returns what ended the refinement (empty when none ran), for
// the stop's reason.
std::string refine_by_self_differences(Search& s, const StudyResult& result, const Solve& solve, double spent,
                                       const std::function<bool()>& stop,
                                       std::vector<std::optional<OrderExtrapolation>>& extrapolations);

}  // namespace dlpverify::search_phase
