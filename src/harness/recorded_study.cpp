#include "dlpverify/recorded_study.hpp"

#include <cmath>

#include "dlpverify/errors.hpp"
#include "dlpverify/report.hpp"
#include "io/format.hpp"
#include "io/json_fields.hpp"
#include "io/input_file.hpp"

namespace dlpverify {

namespace {

using nlohmann::json;

std::string show(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

// The keys of a result that make two studies comparable (the integrator is not one of them).
constexpr const char* kIdentityKeys[] = {"case", "reference", "particles", "t0", "t_end", "ratio", "variables", "parameters"};

// A member that must be there, or InputError naming the file and the key.
const json& member(const json& j, const std::string& key, const std::string& quantity, const std::string& source) {
  if (!j.is_object() || !j.contains(key))
    throw InputError(quantity, source, "is not a converge or check result: it has no \"" + key + "\"");
  return j.at(key);
}

std::optional<double> optional_number(const json& j, const std::string& key) {
  const double x = number_or_nan(j, key);
  return std::isnan(x) ? std::nullopt : std::optional<double>(x);
}

std::optional<RecordedConstant> read_constant(const json& c) {
  if (!c.is_object()) return std::nullopt;
  RecordedConstant constant;
  constant.value = number_or_nan(c, "value");
  constant.order = number_or_nan(c, "order");
  const json ci = member_or(c, "ci95", json());
  constant.ci_low = ci.is_array() && ci.size() == 2 && ci[0].is_number() ? ci[0].get<double>() : std::nan("");
  constant.ci_high = ci.is_array() && ci.size() == 2 && ci[1].is_number() ? ci[1].get<double>() : std::nan("");
  for (const json& k : member_or(c, "levels_used", json::array()))
    if (k.is_number_integer()) constant.levels.push_back(k.get<int>());
  if (!std::isfinite(constant.value) || !std::isfinite(constant.order)) return std::nullopt;
  return constant;
}

// Both numbers are the same double written and read back, or agree to 1e-12 relative.
bool same_number(double a, double b) { return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

}  // namespace

RecordedStudy read_recorded_study(const json& result, const std::string& source, const std::string& quantity) {
  RecordedStudy study;
  study.source = source;
  study.integrator = member_or(result, "integrator", std::string("?"));
  study.identity = json::object();
  for (const char* key : kIdentityKeys) study.identity[key] = member(result, key, quantity, source);
  const json& levels = member(result, "levels", quantity, source);
  const json& constants = member(result, "error_constant", quantity, source);
  const json& fits = member(result, "fitted_order", quantity, source);
  if (!levels.is_array() || levels.empty()) throw InputError(quantity, source, "has no levels");
  for (const json& level : levels) {
    study.dt.push_back(number_or_nan(level, "dt"));
    study.steps.push_back(member_or(level, "steps", 0L));
  }
  for (const json& name : member(result, "variables", quantity, source)) {
    RecordedVariable v;
    v.name = name.is_string() ? name.get<std::string>() : show(name);
    for (const json& level : levels) {
      v.error.push_back(number_or_nan(level, "l2_" + v.name));
      v.pairwise.push_back(optional_number(level, "order_" + v.name));
    }
    const json fit = member_or(fits, v.name, json::object());
    v.order = optional_number(fit, "value");
    v.exact_to_round_off = member_or(fit, "exact_to_round_off", false);
    v.constant = read_constant(member_or(constants, v.name, json()));
    study.variables.push_back(std::move(v));
  }
  return study;
}

RecordedStudy read_recorded_study_file(const std::string& path, const std::string& quantity) {
  const json result = json::parse(read_input_file(quantity, path, input_limit::result), nullptr, false);
  if (result.is_discarded() || !result.is_object()) throw InputError(quantity, path, "is not a JSON result");
  return read_recorded_study(result, path, quantity);
}

std::vector<RecordedVariable> recorded_variables(const StudyResult& study) {
  std::vector<RecordedVariable> variables;
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    const OrderAnalysis& a = study.orders[v];
    RecordedVariable r;
    r.name = study.plan.variables[v].name;
    for (const LevelResult& level : study.levels) r.error.push_back(level.norms[v].l2);
    r.pairwise = a.pairwise;
    if (a.fit.valid) r.order = a.fit.value;
    r.exact_to_round_off = a.exact_to_round_off;
    if (a.constant.valid)
      r.constant = RecordedConstant{a.constant.value, a.constant.order, a.constant.ci_low, a.constant.ci_high, a.constant.levels};
    variables.push_back(std::move(r));
  }
  return variables;
}

RecordedStudy recorded_study(const StudyDescription& description, const StudyResult& study, const std::string& source) {
  RecordedStudy recorded;
  recorded.source = source;
  recorded.integrator = description.integrator;
  recorded.identity = study_identity(description, study);
  for (const LevelResult& level : study.levels) {
    recorded.dt.push_back(level.dt);
    recorded.steps.push_back(level.steps);
  }
  recorded.variables = recorded_variables(study);
  return recorded;
}

std::string study_difference(const RecordedStudy& a, const RecordedStudy& b) {
  for (const char* key : kIdentityKeys) {
    const json &x = a.identity[key], &y = b.identity[key];
    if (x == y || (x.is_number() && y.is_number() && same_number(x.get<double>(), y.get<double>()))) continue;
    if (x.is_object() && y.is_object())  // the parameters: name the first that differs
      for (const auto& [name, value] : x.items())
        if (!y.contains(name) || y[name] != value)
          return std::string(key) + " " + name + " is " + (y.contains(name) ? show(y[name]) : "absent") + ", not " +
                 show(value);
    return std::string("its ") + key + " is " + show(y) + ", not " + show(x);
  }
  if (a.dt.size() != b.dt.size())
    return "it has " + std::to_string(b.dt.size()) + " levels, not " + std::to_string(a.dt.size());
  for (std::size_t k = 0; k < a.dt.size(); ++k)
    if (a.steps[k] != b.steps[k] || !same_number(a.dt[k], b.dt[k]))
      return "its level " + std::to_string(k) + " takes " + std::to_string(b.steps[k]) + " steps of dt " +
             printf_string("%.6g", b.dt[k]) + ", not " + std::to_string(a.steps[k]) + " of " + printf_string("%.6g", a.dt[k]);
  return {};
}

}  // namespace dlpverify
