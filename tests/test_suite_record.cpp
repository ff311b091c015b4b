// A suite's study as its journal records it (case_study/suite_record.hpp) reads back as it ended:
// every double bit for bit, a NaN interval (a fit of two levels) as NaN, an inconclusive verdict as
// inconclusive, a study without a verdict with its exit code and line; a record that is not one is
// refused.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "case_study/suite_record.hpp"

namespace unit_suite_record {

using namespace dlpverify;
using namespace dlpverify::case_study;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

SuiteStudy passed_and_failed() {
  SuiteStudy study;
  study.name = "drag-rk2 (2)";
  study.file = "verification/drag-rk2.toml";
  study.seconds = 0.1 + 0.2;  // 0.30000000000000004: no short decimal
  CaseOutcome outcome(kExitCheckFailed, "console\n");
  outcome.table = "table\n";
  outcome.study = study.name;
  outcome.seconds = study.seconds;
  outcome.report = {{"case", "drag"}, {"levels", {1, 2}}};
  // Member by member: GCC 12 takes a nested brace initialiser's vector for uninitialised.
  VariableVerdict position;
  position.variable = "position";
  position.expected = 2.0;
  position.fit.valid = true;
  position.fit.value = 2.0 / 3.0 + 1.0;
  position.fit.stderr_ = 1e-17 / 3.0;
  position.fit.ci_low = 1.0 / 7.0;
  position.fit.ci_high = 4.0 / 3.0;
  position.fit.levels = {1, 2, 3, 4};
  position.finding = "pass, fitted order 2.023";
  VariableVerdict velocity;
  velocity.variable = "velocity";
  velocity.result = VariableVerdict::Result::fail;
  velocity.expected = 2.0;
  velocity.fit.valid = true;
  velocity.fit.value = 1.0;
  velocity.fit.stderr_ = velocity.fit.ci_low = velocity.fit.ci_high = std::numeric_limits<double>::quiet_NaN();
  velocity.fit.levels = {3, 4};
  velocity.finding = "FAIL";
  VariableVerdict energy;
  energy.variable = "energy";
  energy.result = VariableVerdict::Result::inconclusive;
  energy.expected = 3.0;
  energy.tolerance = 0.1 + 0.2;
  energy.constant.valid = true;
  energy.constant.order = 3.0;
  energy.constant.value = 1.0 / 3.0;
  energy.constant.log_stderr = energy.constant.ci_low = energy.constant.ci_high = std::numeric_limits<double>::quiet_NaN();
  energy.constant.levels = {2, 3};
  energy.finding = "INCONCLUSIVE, still moving";
  energy.quantity = "exponent";
  outcome.verdicts = {position, velocity, energy};
  study.outcome = outcome;
  return study;
}

BOOST_AUTO_TEST_SUITE(suite_record)

BOOST_AUTO_TEST_CASE(a_study_reads_back_bit_for_bit) {
  const SuiteStudy written = passed_and_failed();
  const nlohmann::json line = nlohmann::json::parse(suite_study_json(written).dump());  // as the journal's line reads
  const SuiteStudy read = suite_study_from_json(line);
  BOOST_TEST(read.name == "drag-rk2 (2)");
  BOOST_TEST(read.file == "verification/drag-rk2.toml");
  BOOST_TEST(same_bits(read.seconds, 0.1 + 0.2));
  BOOST_REQUIRE(read.outcome);
  BOOST_TEST(read.exit_code() == kExitCheckFailed);
  BOOST_TEST(read.outcome->console == "console\n");
  BOOST_TEST(read.outcome->table == "table\n");
  BOOST_TEST(read.outcome->report == written.outcome->report);
  BOOST_REQUIRE(read.outcome->verdicts.size() == 3u);
  const OrderFit& fit = read.outcome->verdicts[0].fit;
  BOOST_TEST(same_bits(fit.value, 2.0 / 3.0 + 1.0));
  BOOST_TEST(same_bits(fit.stderr_, 1e-17 / 3.0));
  BOOST_TEST(same_bits(fit.ci_low, 1.0 / 7.0));
  BOOST_TEST(same_bits(fit.ci_high, 4.0 / 3.0));
  BOOST_TEST(fit.levels == std::vector<int>({1, 2, 3, 4}));
  const VariableVerdict& velocity = read.outcome->verdicts[1];
  BOOST_TEST((velocity.result == VariableVerdict::Result::fail));
  BOOST_TEST(velocity.finding == "FAIL");
  BOOST_TEST((std::isnan(velocity.fit.stderr_) && std::isnan(velocity.fit.ci_low) && std::isnan(velocity.fit.ci_high)));
  // Inconclusive reads back as inconclusive (read as a failure, a resumed suite would fail a study).
  const VariableVerdict& energy = read.outcome->verdicts[2];
  BOOST_TEST((energy.result == VariableVerdict::Result::inconclusive));
  BOOST_TEST(same_bits(energy.tolerance, 0.1 + 0.2));
  BOOST_TEST(energy.constant.valid);
  BOOST_TEST(same_bits(energy.constant.order, 3.0));
  BOOST_TEST(same_bits(energy.constant.value, 1.0 / 3.0));
  BOOST_TEST((std::isnan(energy.constant.log_stderr) && std::isnan(energy.constant.ci_low) && std::isnan(energy.constant.ci_high)));
  BOOST_TEST(energy.constant.levels == std::vector<int>({2, 3}));
  BOOST_TEST(energy.quantity == "exponent");
  BOOST_TEST(read.outcome->verdicts[0].quantity == "order");
}

BOOST_AUTO_TEST_CASE(an_inconclusive_study_reads_back_inconclusive) {
  SuiteStudy study = passed_and_failed();
  study.outcome->exit_code = kExitInconclusive;
  for (VariableVerdict& v : study.outcome->verdicts) v.result = VariableVerdict::Result::inconclusive;
  const SuiteStudy read = suite_study_from_json(nlohmann::json::parse(suite_study_json(study).dump()));
  BOOST_TEST(read.exit_code() == kExitInconclusive);
  for (const VariableVerdict& v : read.outcome->verdicts) BOOST_TEST((v.result == VariableVerdict::Result::inconclusive));
}

BOOST_AUTO_TEST_CASE(a_study_without_a_verdict_keeps_its_code_and_line) {
  SuiteStudy bad;
  bad.name = "unknown-case";
  bad.file = "unknown-case.toml";
  bad.code = kExitBadInput;
  bad.error = "--case = nope: unknown case";
  const SuiteStudy read = suite_study_from_json(suite_study_json(bad));
  BOOST_TEST(!read.outcome);
  BOOST_TEST(read.exit_code() == kExitBadInput);
  BOOST_TEST(read.error == "--case = nope: unknown case");
}

BOOST_AUTO_TEST_CASE(a_record_that_is_not_a_study_is_refused) {
  nlohmann::json line = suite_study_json(passed_and_failed());
  line["outcome"]["verdicts"][0]["result"] = "maybe";
  BOOST_CHECK_THROW(suite_study_from_json(line), std::invalid_argument);
  BOOST_CHECK_THROW(suite_study_from_json(nlohmann::json::object()), nlohmann::json::exception);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_suite_record
