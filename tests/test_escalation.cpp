// The escalation's rules (study/escalation.hpp), each at its edge, with a judge that hands out
// verdicts in a given order instead of solving: which undecided checks escalate (levels at the
// round-off floor or the reference's accuracy, an integrator and a problem extended precision can
// step, a reference other than a manufactured solution, escalation asked), and when the refining
// stops (the same decided verdict at two level counts in a row, four levels more unless the orders
// still approach P, the budget);
// and an undecided check of fixed levels that reached no floor searches finer levels in double.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <functional>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "dlpverify/study.hpp"
#include "study/escalation.hpp"

namespace unit_escalation {

using namespace dlpverify;

namespace {

// An outcome of `levels` levels whose one variable's finding is `outcome`, the levels of status `status`.
JudgedStudy judged(CheckOutcome outcome, int levels = 3, LevelStatus status = LevelStatus::round_off) {
  JudgedStudy study;
  StudyOutcome& o = study.outcome;
  o.reported = true;
  o.result.plan.ratio = 2.0;
  for (int k = 0; k < levels; ++k) {
    LevelResult level;
    level.level = k;
    level.dt = 1e-3 / (1 << k);
    level.steps = 10L << k;
    o.result.levels.push_back(level);
  }
  o.result.orders.resize(1);
  o.result.orders[0].status.assign(levels, LevelStatus::ok);
  o.result.orders[0].status.back() = status;
  CheckVerdict verdict;
  verdict.findings.push_back(Finding{0, "position", Criterion::order, outcome, "why"});
  o.verdict = verdict;
  return study;
}

StudyRequest checked() {
  StudyRequest request;
  request.check.emplace();
  request.check->order = 2.0;
  return request;
}

// A judge giving `verdicts` in turn (the last again when they run out), recording each plan's levels.
struct Judge {
  std::vector<CheckOutcome> verdicts;
  std::vector<int> levels{};  // of each call
  JudgedStudy operator()(const StudyRequest& request, const StudyProgress&) {
    BOOST_TEST((request.plan.precision == Precision::extended));
    BOOST_TEST((request.reference.kind == ReferenceKind::extended));
    BOOST_TEST(!request.search);
    levels.push_back(request.plan.levels);
    const std::size_t i = std::min(levels.size(), verdicts.size()) - 1;
    return judged(verdicts[i], request.plan.levels, LevelStatus::ok);
  }
};

StudyOutcome escalated(const StudyRequest& request, JudgedStudy first, Judge& judge) {
  return escalate(request, std::move(first), [&judge](const StudyRequest& r, const StudyProgress& p) { return judge(r, p); },
                  [] { return false; });
}

constexpr CheckOutcome pass = CheckOutcome::order_within;
constexpr CheckOutcome undecided = CheckOutcome::inconclusive;
constexpr CheckOutcome miss = CheckOutcome::order_miss;

}  // namespace

BOOST_AUTO_TEST_SUITE(escalation)

BOOST_AUTO_TEST_CASE(a_pass_confirmed_at_one_more_level_ends_it) {
  Judge judge{{pass}, {}};
  const StudyOutcome outcome = escalated(checked(), judged(undecided), judge);
  BOOST_TEST(judge.levels == (std::vector<int>{3, 4}), boost::test_tools::per_element());
  BOOST_REQUIRE(outcome.escalation);
  BOOST_TEST(outcome.escalation->ran);
  BOOST_TEST(outcome.escalation->levels == 4);
  BOOST_TEST(outcome.escalation->double_levels == 3);
  BOOST_TEST(outcome.escalation->double_findings == (std::vector<std::string>{"position: why"}),
             boost::test_tools::per_element());
  BOOST_TEST(!outcome.escalation->budget_spent);
  BOOST_TEST(outcome.verdict->passed());
}

BOOST_AUTO_TEST_CASE(a_verdict_is_decided_only_when_the_same_at_two_level_counts) {
  Judge judge{{pass, undecided, miss, pass, pass}, {}};
  escalated(checked(), judged(undecided), judge);
  BOOST_TEST(judge.levels == (std::vector<int>{3, 4, 5, 6, 7}), boost::test_tools::per_element());
  Judge failing{{miss, miss}, {}};
  BOOST_TEST((escalated(checked(), judged(undecided), failing).verdict->worst() == FindingResult::fail));
  BOOST_TEST(failing.levels.size() == 2u);
}

BOOST_AUTO_TEST_CASE(at_most_four_levels_more) {
  Judge judge{{undecided}, {}};
  const StudyOutcome outcome = escalated(checked(), judged(undecided, 5), judge);
  BOOST_TEST(judge.levels == (std::vector<int>{5, 6, 7, 8, 9}), boost::test_tools::per_element());
  BOOST_TEST(outcome.verdict->inconclusive());
  BOOST_TEST(outcome.escalation->levels == 9);
}

// A judge whose variables' pairwise orders at L levels are 2.5 but the finest, 2.5 + gap(v, L):
// variable v's errors approach P = 2 (gap < 0), stay (0) or move away (> 0). Findings: undecided,
// or, for the variables in `decided`, a pass.
struct OrdersJudge {
  std::function<double(std::size_t, int)> gap;
  std::size_t variables = 1;
  std::vector<std::size_t> decided{};
  std::vector<int> levels{};
  JudgedStudy operator()(const StudyRequest& request, const StudyProgress&) {
    const int L = request.plan.levels;
    levels.push_back(L);
    JudgedStudy study = judged(undecided, L, LevelStatus::ok);
    StudyOutcome& o = study.outcome;
    o.result.orders.resize(variables);
    o.verdict->findings.clear();
    o.verdict->expected_order = 2.0;
    o.verdict->tolerance = 0.1;
    for (std::size_t v = 0; v < variables; ++v) {
      o.result.orders[v].status.assign(static_cast<std::size_t>(L), LevelStatus::ok);
      o.result.orders[v].pairwise.assign(static_cast<std::size_t>(L), 2.5);
      o.result.orders[v].pairwise.front().reset();  // none on level 0
      *o.result.orders[v].pairwise.back() += gap(v, L);
      const bool pass = std::find(decided.begin(), decided.end(), v) != decided.end();
      o.verdict->findings.push_back(Finding{v, v == 0 ? "x" : "y", Criterion::order, pass ? CheckOutcome::order_within : undecided, "why"});
    }
    return study;
  }
};

std::vector<int> escalated_levels(OrdersJudge judge) {
  escalate(checked(), judged(undecided, 5), [&judge](const StudyRequest& r, const StudyProgress& p) { return judge(r, p); },
           [] { return false; });
  return judge.levels;
}

// Past four levels more, the escalation goes on while every undecided variable's finest order is
// closer to P than the one before by more than tolerance/10 (0.01 here), up to kMostLevels.
BOOST_AUTO_TEST_CASE(past_four_levels_more_only_while_the_orders_approach_p) {
  const auto approaching = [](std::size_t, int L) { return L < 11 ? -0.05 : -0.005; };  // settles at 11 levels
  const std::vector<int> to_11{5, 6, 7, 8, 9, 10, 11}, to_9{5, 6, 7, 8, 9};
  BOOST_TEST(escalated_levels({approaching}) == to_11, boost::test_tools::per_element());
  std::vector<int> to_most(kMostLevels - 4);  // never settling: kMostLevels ends it
  std::iota(to_most.begin(), to_most.end(), 5);
  BOOST_TEST(escalated_levels({[](std::size_t, int) { return -0.011; }}) == to_most, boost::test_tools::per_element());
  BOOST_TEST(escalated_levels({[](std::size_t, int) { return -0.009; }}) == to_9, boost::test_tools::per_element());
  BOOST_TEST(escalated_levels({[](std::size_t, int) { return 0.05; }}) == to_9, boost::test_tools::per_element());
  // Every undecided variable: one that stays ends it; one decided does not count.
  const auto first_approaches = [&](std::size_t v, int L) { return v == 0 ? approaching(v, L) : 0.0; };
  BOOST_TEST(escalated_levels({first_approaches, 2}) == to_9, boost::test_tools::per_element());
  BOOST_TEST(escalated_levels({first_approaches, 2, {1}}) == to_11, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_spent_budget_ends_it_with_the_verdict_it_has) {
  StudyRequest request = checked();
  request.escalation_budget_seconds = 0.0;
  Judge judge{{pass}, {}};
  const StudyOutcome outcome = escalated(request, judged(undecided), judge);
  BOOST_TEST(judge.levels.size() == 1u);
  BOOST_TEST(outcome.escalation->budget_spent);
}

BOOST_AUTO_TEST_CASE(only_an_undecided_check_at_a_floor_escalates) {
  for (const LevelStatus floor : {LevelStatus::round_off, LevelStatus::reference}) {
    Judge judge{{pass}, {}};
    escalated(checked(), judged(undecided, 3, floor), judge);
    BOOST_TEST(judge.levels.size() == 2u);
  }
  Judge judge{{pass}, {}};
  for (const CheckOutcome decided : {pass, miss}) BOOST_TEST(!escalated(checked(), judged(decided), judge).escalation);
  StudyRequest unchecked = checked();
  unchecked.check.reset();
  BOOST_TEST(!escalated(unchecked, judged(undecided), judge).escalation);
  StudyRequest single = checked();
  single.escalate = false;
  BOOST_TEST(!escalated(single, judged(undecided), judge).escalation);
  BOOST_TEST(judge.levels.empty());
}

BOOST_AUTO_TEST_CASE(what_extended_precision_cannot_step_says_why) {
  Judge judge{{pass}, {}};
  JudgedStudy cvode = judged(undecided);
  cvode.extended_refusal = "cvode steps in double only";
  StudyOutcome outcome = escalated(checked(), cvode, judge);
  BOOST_REQUIRE(outcome.escalation);
  BOOST_TEST(!outcome.escalation->ran);
  BOOST_TEST(outcome.escalation->not_possible == "cvode steps in double only");
  BOOST_TEST(outcome.verdict->inconclusive());
  StudyRequest manufactured = checked();
  manufactured.reference.kind = ReferenceKind::manufactured;
  outcome = escalated(manufactured, judged(undecided), judge);
  BOOST_TEST(outcome.escalation->not_possible.find("manufactured") != std::string::npos);
  BOOST_TEST(judge.levels.empty());
}

// Before each level the budget is asked again, the level's cost taken as r = 2 times the one
// before's: a level of 51 s leaves a 100 s budget no room for the next (102 s), one of 49 s does
// (98 s). Stopped in the first round, nothing ran and the report says the budget was spent;
// stopped in the second, the first round's verdict stands.
BOOST_AUTO_TEST_CASE(a_level_that_cannot_finish_in_the_budget_does_not_start) {
  // A study of 100 s budget whose judge finishes one level of `next_seconds()` s a round, asks
  // whether to go on, and stays undecided; `rounds` counts its calls.
  const auto budgeted = [](const std::function<double()>& next_seconds, int& rounds) {
    StudyRequest request = checked();
    request.escalation_budget_seconds = 100.0;
    return escalate(
        request, judged(undecided),
        [&](const StudyRequest& r, const StudyProgress& progress) {
          ++rounds;
          LevelResult level;
          level.wall_seconds = next_seconds();
          progress.finished(level);
          if (progress.stop()) throw StudyStopped(1);
          return judged(undecided, r.plan.levels, LevelStatus::ok);
        },
        [] { return false; });
  };
  for (const double level_seconds : {49.0, 51.0}) {
    int rounds = 0;
    const StudyOutcome outcome = budgeted([level_seconds] { return level_seconds; }, rounds);
    BOOST_REQUIRE(outcome.escalation);
    BOOST_TEST(outcome.escalation->budget_spent == (level_seconds == 51.0));
    BOOST_TEST(outcome.escalation->ran == (level_seconds == 49.0));
    if (level_seconds == 51.0) {
      BOOST_TEST(rounds == 1);
      BOOST_TEST(outcome.escalation->not_possible.find("budget of 100 s was spent") != std::string::npos,
                 outcome.escalation->not_possible);
    }
  }
  // The second round stopped: the first round's 3 levels stand.
  double seconds = 10.0;
  int rounds = 0;
  const StudyOutcome outcome = budgeted([&seconds] { return std::exchange(seconds, 6.0 * seconds); }, rounds);  // 10 s, 60 s
  BOOST_TEST(outcome.escalation->ran);
  BOOST_TEST(outcome.escalation->budget_spent);
  BOOST_TEST(outcome.escalation->levels == 3);
  BOOST_TEST(outcome.result.levels.size() == 3u);
}

// No variable at a floor: a level search from the first study's coarsest level, in the same
// arithmetic against the same reference (a manufactured one too), within the escalation's budget,
// run once (the search confirms its own window). A first study in extended precision, which a
// search cannot run in, ends as it is.
BOOST_AUTO_TEST_CASE(undecided_above_every_floor_searches_finer_levels) {
  for (const ReferenceKind kind : {ReferenceKind::exact, ReferenceKind::manufactured}) {
    StudyRequest request = checked();
    request.reference.kind = kind;
    request.escalation_budget_seconds = 7.0;
    std::vector<double> budgets, coarsest;
    const StudyOutcome outcome = escalate(
        request, judged(undecided, 3, LevelStatus::pre_asymptotic),
        [&](const StudyRequest& r, const StudyProgress&) {
          BOOST_TEST((r.reference.kind == kind));
          BOOST_TEST((r.plan.precision == Precision::double_precision));
          BOOST_REQUIRE(r.search);
          budgets.push_back(r.search->budget_seconds);
          coarsest.push_back(r.plan.coarsest_dt);
          return judged(pass, 6, LevelStatus::ok);
        },
        [] { return false; });
    BOOST_TEST(budgets == (std::vector<double>{7.0}), boost::test_tools::per_element());
    BOOST_TEST(coarsest == (std::vector<double>{1e-3}), boost::test_tools::per_element());
    BOOST_REQUIRE(outcome.escalation);
    BOOST_TEST((outcome.escalation->means == Escalation::Means::finer_levels));
    BOOST_TEST(outcome.escalation->ran);
    BOOST_TEST(outcome.escalation->levels == 6);
    BOOST_TEST(outcome.escalation->double_findings == (std::vector<std::string>{"position: why"}),
               boost::test_tools::per_element());
    BOOST_TEST(outcome.verdict->passed());
  }
  StudyRequest extended = checked();
  extended.plan.precision = Precision::extended;
  Judge judge{{pass}, {}};
  BOOST_TEST(!escalated(extended, judged(undecided, 3, LevelStatus::ok), judge).escalation);
  BOOST_TEST(judge.levels.empty());
}

// A search of finer levels that ends undecided with a level at the round-off floor goes on in
// extended precision from the search's levels (its 6 here), the budget left to it what the search
// did not spend; one that ends decided, or undecided above every floor, or whose method extended
// precision cannot step, ends as the search left it.
BOOST_AUTO_TEST_CASE(a_finer_search_that_reaches_a_floor_goes_on_beyond_double) {
  struct Case {
    CheckOutcome searched;
    LevelStatus finest;
    std::string refusal;
    bool beyond_double;
  };
  for (const Case& c : {Case{undecided, LevelStatus::round_off, "", true}, Case{undecided, LevelStatus::ok, "", false},
                        Case{pass, LevelStatus::round_off, "", false},
                        Case{undecided, LevelStatus::round_off, "held as doubles", false}}) {
    StudyRequest request = checked();
    std::vector<int> extended_levels;
    JudgedStudy first = judged(undecided, 3, LevelStatus::pre_asymptotic);
    first.extended_refusal = c.refusal;
    const StudyOutcome outcome = escalate(
        request, std::move(first),
        [&](const StudyRequest& r, const StudyProgress&) {
          if (r.search) {
            JudgedStudy searched = judged(c.searched, 6, c.finest);
            searched.extended_refusal = c.refusal;
            return searched;
          }
          BOOST_TEST((r.plan.precision == Precision::extended));
          extended_levels.push_back(r.plan.levels);
          return judged(pass, r.plan.levels, LevelStatus::ok);
        },
        [] { return false; });
    BOOST_REQUIRE(outcome.escalation);
    BOOST_TEST((outcome.escalation->means == (c.beyond_double ? Escalation::Means::extended_precision
                                                              : Escalation::Means::finer_levels)));
    BOOST_TEST(outcome.escalation->searched_levels == (c.beyond_double ? 6 : 0));
    BOOST_TEST(extended_levels == (c.beyond_double ? std::vector<int>{6, 7} : std::vector<int>{}),
               boost::test_tools::per_element());
    BOOST_TEST(outcome.result.levels.size() == (c.beyond_double ? 7u : 6u));
  }
}

// A level search chose its levels and said why it stopped: undecided above every floor, it ends.
BOOST_AUTO_TEST_CASE(a_search_undecided_above_every_floor_ends_as_it_is) {
  StudyRequest request = checked();
  request.search.emplace();
  Judge judge{{pass}, {}};
  BOOST_TEST(!escalated(request, judged(undecided, 3, LevelStatus::ok), judge).escalation);
  BOOST_TEST(judge.levels.empty());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_escalation
