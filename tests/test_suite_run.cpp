// A suite's promises (case_study/suite.hpp, suite_run.hpp, summary.hpp): studies that pass or are
// inconclusive make exit 5, not 0; --jobs 0 runs one study per thread at once (observed: that many
// studies under way together); the Markdown summary lists failures, then studies without a verdict,
// then inconclusive ones, then passes.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "case_study/summary.hpp"
#include "case_study/suite_run.hpp"

namespace unit_suite_run {

using namespace dlpverify;
using namespace dlpverify::case_study;

SuiteStudy ended(const std::string& name, int code) {
  SuiteStudy s;
  s.name = name;
  CaseOutcome outcome(code, "");
  VariableVerdict v;
  v.variable = "position";
  v.result = code == kExitDone ? FindingResult::pass : code == kExitInconclusive ? FindingResult::inconclusive : FindingResult::fail;
  v.expected = 2.0;
  v.finding = code == kExitDone ? "pass, fitted order 2.0" : "FAIL, fitted order 1|0";
  outcome.verdicts = {v};
  s.outcome = outcome;
  return s;
}

BOOST_AUTO_TEST_SUITE(suite_run)

BOOST_AUTO_TEST_CASE(pass_and_inconclusive_exit_5) {
  BOOST_TEST(suite_exit_code({ended("a", kExitDone), ended("b", kExitDone)}) == kExitDone);
  BOOST_TEST(suite_exit_code({ended("a", kExitDone), ended("b", kExitInconclusive)}) == kExitInconclusive);
  BOOST_TEST(suite_exit_code({ended("a", kExitInconclusive), ended("b", kExitCheckFailed)}) == kExitCheckFailed);
}

BOOST_AUTO_TEST_CASE(jobs_0_runs_one_study_a_thread) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "dlpverify-unit-suite-run";
  std::filesystem::create_directories(folder);
  SuiteRequest request;
  for (const char* name : {"a.toml", "b.toml", "c.toml"}) {
    std::ofstream(folder / name) << "case = \"drag\"\n";
    request.files.push_back((folder / name).string());
  }
  request.jobs = 0;
  request.threads = 3;
  std::mutex mutex;
  std::condition_variable changed;
  int running = 0, most = 0;
  bool all_at_once = false;
  const auto run = [&](std::size_t) {
    std::unique_lock<std::mutex> lock(mutex);
    most = std::max(most, ++running);
    if (running == 3) all_at_once = true;
    changed.notify_all();
    // Waits for the others to be under way too; one at a time, each gives up after a second.
    changed.wait_for(lock, std::chrono::seconds(1), [&] { return all_at_once; });
    --running;
    return SuiteStudy{};
  };
  const SuiteOutcome outcome = run_suite(request, run, [](const SuiteStudy&, std::size_t, std::size_t) {});
  std::filesystem::remove_all(folder);
  BOOST_TEST(most == 3);
  BOOST_TEST(outcome.studies.size() == 3u);
}

BOOST_AUTO_TEST_CASE(the_summary_lists_failures_first) {
  SuiteStudy broken;
  broken.name = "broken";
  broken.code = kExitSolverFailed;
  broken.error = "CVODE failed";
  const std::string summary =
      suite_summary({ended("passes", kExitDone), ended("undecided", kExitInconclusive), ended("fails", kExitCheckFailed), broken});
  BOOST_TEST(summary.rfind("### dlpverify suite: ERROR (exit 3)\n", 0) == 0u, summary);
  const auto at = [&summary](const std::string& row) { return summary.find(row); };
  const std::string::size_type fails = at("| FAIL | fails | position FAIL, fitted order 1\\|0 |\n"),
                               error = at("| ERROR (exit 3) | broken | CVODE failed |\n"),
                               undecided = at("| INCONCLUSIVE | undecided |"), passes = at("| pass | passes | position - |\n");
  BOOST_TEST((fails != std::string::npos && error != std::string::npos && undecided != std::string::npos &&
              passes != std::string::npos), summary);
  BOOST_TEST((fails < error && error < undecided && undecided < passes), summary);
}

BOOST_AUTO_TEST_CASE(a_check_summary_lists_its_failed_variables_first) {
  SuiteStudy study = ended("drag rk2", kExitCheckFailed);
  VariableVerdict passed = study.outcome->verdicts[0];
  passed.variable = "velocity";
  passed.result = FindingResult::pass;
  passed.finding = "pass, fitted order 2.0";
  study.outcome->verdicts.insert(study.outcome->verdicts.begin(), passed);
  const std::string summary = check_summary(study);
  BOOST_TEST(summary.rfind("### dlpverify check drag rk2: FAIL\n", 0) == 0u, summary);
  BOOST_TEST(summary.find("| FAIL | position |") < summary.find("| pass | velocity |"), summary);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_suite_run
