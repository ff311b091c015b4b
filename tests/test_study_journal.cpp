// Interrupted studies (docs/cli.md, "The journal and --resume"): the study loop stopped between levels and
// continued from the levels it finished gives the uninterrupted study bit for bit; a level's
// record reads back bit for bit (NaN, infinities, −0 and subnormals included); the journal file
// keeps whole lines, leaves out a torn last one, and refuses a second writer.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/dlp.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/work_precision.hpp"
#include "harness/exact_record.hpp"
#include "io/journal_file.hpp"
#include "study/journal.hpp"

namespace unit_study_journal {

using namespace dlpverify;
namespace fs = std::filesystem;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || same_bits(*a, *b));
}

// RK2 on the drag case, R_out 4 (256 particles), its default five levels, against the closed form.
struct DragStudy {
  std::unique_ptr<Problem> problem = dlp::make_problem("drag", {.outer = 4});
  ExplicitRungeKutta<tableau::midpoint> rk2{"rk2"};
  StudyPlan plan;
  State initial = problem->initial_state(), reference;
  int solves = 0;
  DragStudy() {
    const StudyDefaults defaults = dlp::case_defaults("drag");
    plan = {defaults.t_end, defaults.dt, 2.0, defaults.levels, 2.0, problem->variables()};
    reference = problem->measured(closed_form(*problem, initial, plan.t_end), plan.t_end);
  }
  StudyResult run(const StudyProgress& progress = {}) {
    const Solve solve = [this](double dt, long steps, SolverStatistics& statistics) {
      ++solves;
      State state = initial;
      rk2.advance(*problem, state, problem->initial_time(), dt, steps);
      statistics = rk2.statistics();
      return problem->measured(state, plan.t_end);
    };
    return run_study(plan, reference, std::vector<double>(plan.variables.size(), 0.0), solve, progress);
  }
};

// Every number a report shows, bit for bit (wall times aside).
void require_same_study(const StudyResult& a, const StudyResult& b) {
  BOOST_REQUIRE_EQUAL(a.levels.size(), b.levels.size());
  for (std::size_t k = 0; k < a.levels.size(); ++k)
    for (std::size_t v = 0; v < a.plan.variables.size(); ++v) {
      const ErrorNorms &x = a.levels[k].norms[v], &y = b.levels[k].norms[v];
      BOOST_TEST((same_bits(x.l2, y.l2) && same_bits(x.rms, y.rms) && same_bits(x.relative, y.relative) &&
                  same_bits(x.max, y.max) && same_bits(x.reference_l2, y.reference_l2)),
                 "level " << k << " variable " << v);
      BOOST_TEST(same_bits(a.levels[k].self_difference[v], b.levels[k].self_difference[v]), "level " << k);
      BOOST_TEST(same_bits(a.orders[v].pairwise[k], b.orders[v].pairwise[k]));
      BOOST_TEST((a.orders[v].status[k] == b.orders[v].status[k]));
      BOOST_TEST(same_bits(a.self_convergence[v].order[k], b.self_convergence[v].order[k]));
    }
  for (std::size_t v = 0; v < a.plan.variables.size(); ++v) {
    BOOST_TEST(same_bits(a.orders[v].fit.value, b.orders[v].fit.value));
    BOOST_TEST(same_bits(a.orders[v].fit.stderr_, b.orders[v].fit.stderr_));
    BOOST_TEST(same_bits(a.self_convergence[v].richardson_error, b.self_convergence[v].richardson_error));
  }
  BOOST_TEST(((a.finest.array() == b.finest.array()).all()), "the finest state");
}

// The levels a run finished, through their records as a journal holds them (text and back).
std::vector<LevelResult> through_records(const std::vector<std::string>& lines, const std::vector<Variable>& variables) {
  std::vector<LevelResult> levels;
  for (const std::string& line : lines) levels.push_back(level_from_record(nlohmann::json::parse(line), variables));
  return levels;
}

struct TemporaryFolder {
  fs::path path = fs::temp_directory_path() / ("dlpverify-journal-" + std::to_string(::getpid()));
  TemporaryFolder() { fs::create_directories(path); }
  ~TemporaryFolder() { fs::remove_all(path); }
};

std::size_t line_count(const fs::path& file) {
  std::ifstream in(file);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(study_resume)

BOOST_AUTO_TEST_CASE(stopped_then_resumed_equals_uninterrupted) {
  DragStudy whole;
  const StudyResult uninterrupted = whole.run();
  BOOST_TEST(whole.solves == 5);

  DragStudy first;
  std::vector<std::string> journal;
  StudyProgress progress;
  progress.finished = [&](const LevelResult& level) { journal.push_back(level_record(level, first.plan.variables).dump()); };
  progress.stop = [&] { return journal.size() == 2; };  // a signal during level 1
  try {
    first.run(progress);
    BOOST_FAIL("the study was not stopped");
  } catch (const StudyStopped& stopped) {
    BOOST_TEST(stopped.levels_done() == 2);
  }
  BOOST_TEST(first.solves == 2);
  BOOST_REQUIRE(journal.size() == 2u);

  DragStudy second;
  StudyProgress resume;
  resume.done = through_records(journal, second.plan.variables);
  resume.finished = [&](const LevelResult& level) { journal.push_back(level_record(level, second.plan.variables).dump()); };
  const StudyResult resumed = second.run(resume);
  BOOST_TEST(second.solves == 4, "level 1 again for its state, then levels 2–4: " << second.solves);
  BOOST_TEST(journal.size() == 5u);
  require_same_study(uninterrupted, resumed);
}

BOOST_AUTO_TEST_CASE(all_levels_done_solves_only_the_finest_again) {
  DragStudy whole;
  std::vector<std::string> journal;
  StudyProgress progress;
  progress.finished = [&](const LevelResult& level) { journal.push_back(level_record(level, whole.plan.variables).dump()); };
  const StudyResult uninterrupted = whole.run(progress);

  DragStudy again;
  StudyProgress resume;
  resume.done = through_records(journal, again.plan.variables);
  resume.finished = [](const LevelResult&) { BOOST_FAIL("no level is left to finish"); };
  const StudyResult resumed = again.run(resume);
  BOOST_TEST(again.solves == 1);
  require_same_study(uninterrupted, resumed);
}

BOOST_AUTO_TEST_CASE(a_level_that_does_not_solve_again_the_same_is_refused) {
  DragStudy whole;
  std::vector<std::string> journal;
  StudyProgress progress;
  progress.finished = [&](const LevelResult& level) { journal.push_back(level_record(level, whole.plan.variables).dump()); };
  whole.run(progress);

  DragStudy again;
  StudyProgress resume;
  resume.done = through_records({journal[0], journal[1]}, again.plan.variables);
  resume.done[1].norms[1].l2 = std::nextafter(resume.done[1].norms[1].l2, 1.0);  // one ulp: another computation
  BOOST_CHECK_THROW(again.run(resume), InputError);
}

BOOST_AUTO_TEST_CASE(a_level_of_another_plan_is_refused) {
  DragStudy whole;
  std::vector<std::string> journal;
  StudyProgress progress;
  progress.finished = [&](const LevelResult& level) { journal.push_back(level_record(level, whole.plan.variables).dump()); };
  whole.run(progress);

  DragStudy finer;
  finer.plan.coarsest_dt /= 2.0;  // level 0 now takes 40 steps
  StudyProgress resume;
  resume.done = through_records({journal[0]}, finer.plan.variables);
  BOOST_CHECK_THROW(finer.run(resume), InputError);
  BOOST_TEST(finer.solves == 0);
}

// The library's journal, stopped after two levels, is refused when started afresh, refused to
// resume another study, and resumed by this one with its two levels as they were; its messages
// name the controls in the API's words unless the caller names them.
BOOST_AUTO_TEST_CASE(the_study_journal_keeps_refuses_and_resumes) {
  const TemporaryFolder folder;
  const std::string result = (folder.path / "result.json").string();
  const nlohmann::json study = {{"case", "drag"}, {"levels", 5}};
  DragStudy first;
  std::vector<std::string> notices;
  JournalTerms terms;
  terms.notice = [&notices](const std::string& line) { notices.push_back(line); };
  {
    StudyJournal journal(result, JournalStart::fresh, "converge", {{"ratio", 2}}, study, terms);
    BOOST_REQUIRE(journal.active());
    StudyProgress progress = journal.levels(first.plan.variables);
    int recorded = 0;
    const auto record = progress.finished;
    progress.finished = [&](const LevelResult& level) {
      record(level);
      ++recorded;
    };
    progress.stop = [&recorded] { return recorded == 2; };  // a signal during level 1
    BOOST_CHECK_THROW(first.run(progress), StudyStopped);
  }  // stopped: the journal keeps its header and two levels
  const std::string path = journal_path(result);
  BOOST_TEST(path == result + ".journal.jsonl");
  BOOST_TEST(line_count(path) == 3u);

  try {
    StudyJournal again(result, JournalStart::fresh, "converge", {{"ratio", 2}}, study, terms);
    BOOST_FAIL("an unfinished study's journal was started over");
  } catch (const InputError& e) {
    BOOST_TEST(e.quantity() == "result file");
    BOOST_TEST(e.reason() == "the journal of an unfinished study is beside it (" + path +
                                 ", 2 finished): continue that study with JournalStart::resume, or start over with "
                                 "JournalStart::restart");
  }
  try {
    StudyJournal other(result, JournalStart::resume, "converge", {{"ratio", 3}}, study, terms);
    BOOST_FAIL("another study's journal was resumed");
  } catch (const InputError& e) {
    BOOST_TEST(e.quantity() == "JournalStart::resume");
    BOOST_TEST(e.reason().rfind("option ratio is 3 here, 2 in the journal; ", 0) == 0, e.reason());
  }
  BOOST_TEST(notices.empty());

  DragStudy second;
  StudyJournal journal(result, JournalStart::resume, "converge", {{"ratio", 2}}, study, terms);
  const StudyProgress resume = journal.levels(second.plan.variables);
  BOOST_REQUIRE(resume.done.size() == 2u);
  BOOST_TEST(notices == std::vector<std::string>{"resuming from " + path + " (2 finished, taken as they are)"});
  require_same_study(DragStudy().run(), second.run(resume));
  BOOST_TEST(second.solves == 4, "level 1 again for its state, then levels 2–4: " << second.solves);
  BOOST_TEST(line_count(path) == 6u);
  journal.finish();
  BOOST_TEST(!fs::exists(path));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(level_record_exact)

BOOST_AUTO_TEST_CASE(every_double_reads_back_bit_for_bit) {
  const double nasty[] = {0.1, 1.0 / 3.0, -0.0, 0.0, std::numeric_limits<double>::denorm_min(),
                          std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                          std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN()};
  for (const double x : nasty) BOOST_TEST(same_bits(exact_number(exact_text(x)), x), exact_text(x));

  const std::vector<Variable> variables = {{"position", 0, 3, "m"}, {"velocity", 3, 3, "m/s"}};
  LevelResult level;
  level.level = 3;
  level.steps = 160;
  level.dt = 0.01 / 160.0;
  level.wall_seconds = 0.123456789;
  level.norms = {{0.1, 1.0 / 3.0, std::numeric_limits<double>::denorm_min(), -0.0, 7e300},
                 {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 2.0, 3.0, 4.0}};
  level.self_difference = {std::nullopt, 6.02214076e23};
  level.solver_statistics.steps = 160;
  level.solver_statistics.extras = {{"h_last", 6.103515625e-05 / 3.0}, {"method", std::string("adams")}};

  const std::string line = level_record(level, variables).dump();
  BOOST_TEST(line.find('\n') == std::string::npos);
  const LevelResult back = level_from_record(nlohmann::json::parse(line), variables);
  BOOST_TEST(back.level == 3);
  BOOST_TEST(back.steps == 160);
  BOOST_TEST(same_bits(back.dt, level.dt));
  BOOST_TEST(same_bits(back.wall_seconds, level.wall_seconds));
  for (std::size_t v = 0; v < 2; ++v) {
    const ErrorNorms &a = back.norms[v], &b = level.norms[v];
    BOOST_TEST((same_bits(a.l2, b.l2) && same_bits(a.rms, b.rms) && same_bits(a.relative, b.relative) &&
                same_bits(a.max, b.max) && same_bits(a.reference_l2, b.reference_l2)));
    BOOST_TEST(same_bits(back.self_difference[v], level.self_difference[v]));
  }
  BOOST_TEST(same_bits(back.solver_statistics.extra_real("h_last").value(), 6.103515625e-05 / 3.0));
  BOOST_TEST((back.solver_statistics == level.solver_statistics));
}

BOOST_AUTO_TEST_CASE(a_malformed_record_is_refused) {
  const std::vector<Variable> variables = {{"position", 0, 3, "m"}};
  LevelResult level;
  level.norms = {{1.0, 1.0, 1.0, 1.0, 1.0}};
  level.self_difference = {std::nullopt};
  const nlohmann::json good = level_record(level, variables);
  BOOST_CHECK_NO_THROW(level_from_record(good, variables));

  nlohmann::json decimal = good;
  decimal["variables"]["position"]["l2"] = 0.5;  // a decimal number need not read back exactly
  BOOST_CHECK_THROW(level_from_record(decimal, variables), std::invalid_argument);
  nlohmann::json trailing = good;
  trailing["dt"] = "0x1p-3 and more";
  BOOST_CHECK_THROW(level_from_record(trailing, variables), std::invalid_argument);
  const std::vector<Variable> more = {{"position", 0, 3, "m"}, {"velocity", 3, 3, "m/s"}};
  BOOST_CHECK_THROW(level_from_record(good, more), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(journal_file)

BOOST_AUTO_TEST_CASE(whole_lines_survive_a_torn_last_one) {
  const TemporaryFolder folder;
  const fs::path path = folder.path / "study.json.journal.jsonl";
  BOOST_TEST(!JournalFile::open_existing(path.string()).has_value());
  {
    JournalFile journal = JournalFile::create(path.string());
    for (int k = 0; k < 3; ++k) journal.append({{"level", k}});
    BOOST_CHECK_THROW(JournalFile::create(path.string()), InputError);         // never overwritten
    BOOST_CHECK_THROW(JournalFile::open_existing(path.string()), InputError);  // locked while in use
  }
  std::ofstream(path, std::ios::app) << "{\"level\": 3, \"va";  // a write cut short
  const auto size_with_torn_line = fs::file_size(path);
  {
    std::optional<JournalFile> journal = JournalFile::open_existing(path.string());
    BOOST_REQUIRE(journal.has_value());
    BOOST_TEST(journal->records().size() == 3u);
    BOOST_TEST(journal->records()[2]["level"] == 2);
    BOOST_TEST(journal->found_torn_line());
    BOOST_TEST(fs::file_size(path) == size_with_torn_line, "reading changes nothing");
    journal->append({{"level", 3}});
  }
  std::optional<JournalFile> journal = JournalFile::open_existing(path.string());
  BOOST_REQUIRE(journal.has_value());
  BOOST_TEST(!journal->found_torn_line());
  BOOST_TEST(journal->records().size() == 4u);
  BOOST_TEST(journal->records()[3]["level"] == 3);
  BOOST_TEST(line_count(path) == 4u);
  journal->remove();
  BOOST_TEST(!fs::exists(path));
}

BOOST_AUTO_TEST_CASE(a_damaged_whole_line_is_refused) {
  const TemporaryFolder folder;
  const fs::path path = folder.path / "damaged.jsonl";
  std::ofstream(path) << "{\"level\": 0}\nnot json\n{\"level\": 1}\n";
  BOOST_CHECK_THROW(JournalFile::open_existing(path.string()), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(precision_resume)

// RK2 on drag (R_out 4) at three steps, a work-precision sweep of fixed-step runs.
struct Sweep {
  std::unique_ptr<Problem> problem = dlp::make_problem("drag", {.outer = 4});
  State initial = problem->initial_state();
  const double t_end = 0.01;
  State reference = problem->measured(closed_form(*problem, initial, t_end), t_end);
  int solves = 0;
  std::vector<PrecisionRun> runs() {
    std::vector<PrecisionRun> sweep;
    for (const long steps : {20L, 40L, 80L}) {
      const double dt = t_end / static_cast<double>(steps);
      sweep.push_back({"rk2", std::nullopt, dt, [this, dt, steps](SolverStatistics& statistics) {
                         ++solves;
                         ExplicitRungeKutta<tableau::midpoint> rk2("rk2");
                         State state = initial;
                         rk2.advance(*problem, state, problem->initial_time(), dt, steps);
                         statistics = rk2.statistics();
                         return problem->measured(state, t_end);
                       }});
    }
    return sweep;
  }
  WorkPrecisionResult run(const Progress<PrecisionRunResult>& progress = {}) {
    return run_work_precision(runs(), reference, {}, problem->variables(), progress);
  }
};

BOOST_AUTO_TEST_CASE(stopped_then_resumed_equals_uninterrupted) {
  Sweep whole;
  const WorkPrecisionResult uninterrupted = whole.run();

  Sweep first;
  const std::vector<Variable> variables = first.problem->variables();
  std::vector<std::string> journal;
  Progress<PrecisionRunResult> progress;
  progress.finished = [&](const PrecisionRunResult& run) { journal.push_back(run_record(run, variables).dump()); };
  progress.stop = [&] { return journal.size() == 1; };
  BOOST_CHECK_THROW(first.run(progress), StudyStopped);
  BOOST_TEST(first.solves == 1);

  Sweep second;
  Progress<PrecisionRunResult> resume;
  resume.done.push_back(run_from_record(nlohmann::json::parse(journal[0]), variables));
  const WorkPrecisionResult resumed = second.run(resume);
  BOOST_TEST(second.solves == 2, "a finished run is not solved again");
  BOOST_REQUIRE(resumed.runs.size() == 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const PrecisionRunResult &a = uninterrupted.runs[i], &b = resumed.runs[i];
    BOOST_TEST((a.steps == b.steps && a.rhs_evals == b.rhs_evals && same_bits(*a.dt, *b.dt)));
    for (std::size_t v = 0; v < variables.size(); ++v)
      BOOST_TEST((same_bits(a.norms[v].l2, b.norms[v].l2) && same_bits(a.norms[v].max, b.norms[v].max) &&
                  same_bits(a.reference_margin[v], b.reference_margin[v])));
  }

  Sweep other;
  Progress<PrecisionRunResult> wrong;
  wrong.done = resume.done;
  wrong.done[0].dt = *wrong.done[0].dt / 2.0;  // a run of another sweep
  BOOST_CHECK_THROW(other.run(wrong), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_study_journal
