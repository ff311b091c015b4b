#include "case_study/ci_report.hpp"

#include <cmath>
#include <filesystem>

#include "io/format.hpp"

namespace dlpverify::case_study {

using Result = VariableVerdict::Result;

std::vector<VariableVerdict> variable_verdicts(const std::vector<Variable>& variables, const CheckVerdict& verdict) {
  std::vector<VariableVerdict> verdicts;
  for (std::size_t v = 0; v < variables.size(); ++v) {
    const Finding* worst = verdict.worst_of(v);
    if (!worst) continue;
    VariableVerdict row;
    row.variable = variables[v].name;
    row.expected = verdict.expected_order;
    row.tolerance = verdict.tolerance;
    row.result = worst->result();
    row.finding = worst->text;
    verdicts.push_back(std::move(row));
  }
  return verdicts;
}

std::vector<VariableVerdict> variable_verdicts(const StudyResult& study, const CheckVerdict& verdict) {
  std::vector<VariableVerdict> verdicts = variable_verdicts(study.plan.variables, verdict);
  for (VariableVerdict& row : verdicts)
    for (std::size_t v = 0; v < study.plan.variables.size(); ++v)
      if (study.plan.variables[v].name == row.variable) {
        if (v < verdict.expected_orders.size()) row.expected = verdict.expected_orders[v];
        if (v < study.orders.size()) {
          row.fit = study.orders[v].fit;
          row.constant = study.orders[v].constant;
        }
      }
  return verdicts;
}

std::string study_name(const std::string& config, const std::string& case_name, const std::string& integrator) {
  return config.empty() ? case_name + " " + integrator : std::filesystem::path(config).stem().string();
}

namespace {

// A message attribute is one line: a reporter shows it as a heading.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

std::vector<JunitProperty> junit_properties(const std::vector<VariableVerdict>& verdicts) {
  std::vector<JunitProperty> properties;
  const auto add = [&properties](const VariableVerdict& v, const std::string& what, double value) {
    if (std::isfinite(value)) properties.push_back({v.variable + "." + what, printf_string("%.6g", value)});
  };
  for (const VariableVerdict& v : verdicts) {
    const std::string& q = v.quantity;
    if (v.fit.valid) {
      add(v, q, v.fit.value);
      add(v, q + "_low", v.fit.ci_low);
      add(v, q + "_high", v.fit.ci_high);
    }
    add(v, "expected_" + q, v.expected);
    add(v, q + "_tolerance", v.tolerance);
    // A trend of C at the expected order: a constant fitted at another (the order the errors
    // show, when they miss P) is no point of that trend.
    if (v.constant.valid && v.constant.order == v.expected) add(v, "error_constant", v.constant.value);
  }
  return properties;
}

JunitSuite junit_suite(const std::string& name, const CaseOutcome& outcome) {
  JunitSuite suite{name, outcome.seconds, {}, junit_properties(outcome.verdicts)};
  for (const VariableVerdict& v : outcome.verdicts) {
    // The variables share the study's time: each case takes its share, so the suite's time is the sum.
    const double share = outcome.seconds / static_cast<double>(outcome.verdicts.size());
    JunitCase c{v.variable, name, share, JunitCase::Result::passed, {}, {}};
    if (v.result != Result::pass) {
      c.result = v.result == Result::fail ? JunitCase::Result::failure : JunitCase::Result::skipped;
      c.message = one_line(v.variable + ": " + v.finding);
      // GitLab shows a failure's text alone (its message attribute not at all): the finding first.
      c.body = c.message + "\n\n" + outcome.table;
    }
    suite.cases.push_back(std::move(c));
  }
  return suite;
}

JunitSuite junit_error_suite(const std::string& name, int code, const std::string& line, double seconds) {
  JunitCase c{"study", name, seconds, JunitCase::Result::error, one_line(line), printf_string("%s\n\nexit code %d", line.c_str(), code)};
  return {name, seconds, {std::move(c)}, {}};
}

}  // namespace dlpverify::case_study
