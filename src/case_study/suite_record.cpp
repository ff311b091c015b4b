#include "case_study/suite_record.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace dlpverify::case_study {

namespace {

using json = nlohmann::json;
using Result = VariableVerdict::Result;

json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }
double number_of(const json& j) { return j.is_null() ? std::numeric_limits<double>::quiet_NaN() : j.get<double>(); }

const char* result_name(Result r) { return r == Result::pass ? "pass" : r == Result::fail ? "fail" : "inconclusive"; }
Result result_of(const std::string& name) {
  if (name == "pass") return Result::pass;
  if (name == "fail") return Result::fail;
  if (name == "inconclusive") return Result::inconclusive;
  throw std::invalid_argument("unknown verdict \"" + name + "\"");
}

json fit_json(const OrderFit& fit) {
  return {{"valid", fit.valid},        {"value", number(fit.value)},     {"stderr", number(fit.stderr_)},
          {"ci_low", number(fit.ci_low)}, {"ci_high", number(fit.ci_high)}, {"levels", fit.levels}};
}
OrderFit fit_of(const json& j) {
  OrderFit fit;
  fit.valid = j.at("valid").get<bool>();
  fit.value = number_of(j.at("value"));
  fit.stderr_ = number_of(j.at("stderr"));
  fit.ci_low = number_of(j.at("ci_low"));
  fit.ci_high = number_of(j.at("ci_high"));
  fit.levels = j.at("levels").get<std::vector<int>>();
  return fit;
}

json constant_json(const ErrorConstant& c) {
  return {{"valid", c.valid},           {"order", number(c.order)},     {"value", number(c.value)},
          {"log_stderr", number(c.log_stderr)}, {"ci_low", number(c.ci_low)}, {"ci_high", number(c.ci_high)},
          {"levels", c.levels}};
}
ErrorConstant constant_of(const json& j) {
  ErrorConstant c;
  c.valid = j.at("valid").get<bool>();
  c.order = number_of(j.at("order"));
  c.value = number_of(j.at("value"));
  c.log_stderr = number_of(j.at("log_stderr"));
  c.ci_low = number_of(j.at("ci_low"));
  c.ci_high = number_of(j.at("ci_high"));
  c.levels = j.at("levels").get<std::vector<int>>();
  return c;
}

json outcome_json(const CaseOutcome& o) {
  json verdicts = json::array();
  for (const VariableVerdict& v : o.verdicts)
    verdicts.push_back({{"variable", v.variable},
                        {"result", result_name(v.result)},
                        {"expected", number(v.expected)},
                        {"tolerance", number(v.tolerance)},
                        {"fit", fit_json(v.fit)},
                        {"constant", constant_json(v.constant)},
                        {"finding", v.finding},
                        {"quantity", v.quantity}});
  return {{"exit_code", o.exit_code}, {"console", o.console}, {"table", o.table}, {"study", o.study},
          {"seconds", number(o.seconds)}, {"verdicts", verdicts}, {"report", o.report}};
}
CaseOutcome outcome_of(const json& j) {
  CaseOutcome o(j.at("exit_code").get<int>(), j.at("console").get<std::string>());
  o.table = j.at("table").get<std::string>();
  o.study = j.at("study").get<std::string>();
  o.seconds = number_of(j.at("seconds"));
  o.report = j.at("report");
  for (const json& v : j.at("verdicts")) {
    VariableVerdict verdict;
    verdict.variable = v.at("variable").get<std::string>();
    verdict.result = result_of(v.at("result").get<std::string>());
    verdict.expected = number_of(v.at("expected"));
    verdict.tolerance = number_of(v.at("tolerance"));
    verdict.fit = fit_of(v.at("fit"));
    verdict.constant = constant_of(v.at("constant"));
    verdict.finding = v.at("finding").get<std::string>();
    verdict.quantity = v.at("quantity").get<std::string>();
    o.verdicts.push_back(std::move(verdict));
  }
  return o;
}

}  // namespace

json suite_study_json(const SuiteStudy& study) {
  json j = {{"name", study.name},         {"file", study.file},  {"exit_code", study.exit_code()},
            {"error", study.error},       {"seconds", number(study.seconds)}};
  if (study.outcome) j["outcome"] = outcome_json(*study.outcome);
  return j;
}

SuiteStudy suite_study_from_json(const json& record) {
  SuiteStudy study;
  study.name = record.at("name").get<std::string>();
  study.file = record.at("file").get<std::string>();
  study.error = record.at("error").get<std::string>();
  study.seconds = number_of(record.at("seconds"));
  if (record.contains("outcome"))
    study.outcome = outcome_of(record.at("outcome"));
  else
    study.code = record.at("exit_code").get<int>();
  return study;
}

}  // namespace dlpverify::case_study
