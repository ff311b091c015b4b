#include "harness/comparison.hpp"

#include <cmath>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/printable.hpp"

namespace dlpverify {

namespace {

VariableComparison compare_variable(const RecordedVariable& a, const RecordedVariable& b, const ComparisonTolerances& t) {
  VariableComparison v;
  v.name = a.name;
  if (a.exact_to_round_off && b.exact_to_round_off) {
    v.orders_agree = true;
    v.order_text = "exact to round-off in both";
  } else if (a.order && b.order) {
    const double difference = *b.order - *a.order;
    v.orders_agree = std::abs(difference) <= t.order;
    v.order_text = printf_string("fitted order A %.3f, B %.3f (difference %+.3f, %s %g)", *a.order, *b.order, difference,
                                 v.orders_agree ? "within" : "outside", t.order);
  } else {
    v.order_text = std::string("no fitted order in ") + (!a.order && !b.order ? "either" : !a.order ? "A" : "B");
  }
  v.constant = compare_constants(a, b, t.constant);
  return v;
}

std::string optional_text(const std::optional<double>& x, const char* format) {
  return x ? printf_string(format, *x) : std::string("-");
}

// "<var>: <what differs>" for each disagreement of each variable, in the report's order.
std::vector<std::string> disagreements(const StudyComparison& comparison) {
  std::vector<std::string> found;
  for (const VariableComparison& c : comparison.variables) {
    if (!c.orders_agree) found.push_back(c.name + ": " + c.order_text);
    if (!c.constant.agree) found.push_back(c.name + ": " + c.constant.text);
  }
  return found;
}

nlohmann::json optional_json(const std::optional<double>& x) { return x ? number_or_null(*x) : nlohmann::json(); }

nlohmann::json constant_json(const std::optional<RecordedConstant>& c) {
  if (!c) return nlohmann::json();
  return {{"value", number_or_null(c->value)}, {"order", c->order}, {"levels_used", c->levels}};
}

nlohmann::json variable_json(const RecordedStudy& a, const RecordedStudy& b, std::size_t v, const VariableComparison& c) {
  using nlohmann::json;
  const RecordedVariable &x = a.variables[v], &y = b.variables[v];
  json levels = json::array();
  for (std::size_t k = 0; k < a.dt.size(); ++k)
    levels.push_back({{"level", k}, {"dt", a.dt[k]}, {"steps", a.steps[k]}, {"error_a", number_or_null(x.error[k])},
                      {"error_b", number_or_null(y.error[k])}, {"ratio", number_or_null(y.error[k] / x.error[k])},
                      {"order_a", optional_json(x.pairwise[k])}, {"order_b", optional_json(y.pairwise[k])}});
  const json difference = x.order && y.order ? number_or_null(*y.order - *x.order) : json();
  return {{"levels", levels},
          {"exact_to_round_off", {{"a", x.exact_to_round_off}, {"b", y.exact_to_round_off}}},
          {"fitted_order", {{"a", optional_json(x.order)}, {"b", optional_json(y.order)},
                            {"difference", difference}, {"agree", c.orders_agree}, {"text", c.order_text}}},
          {"error_constant", {{"a", constant_json(x.constant)}, {"b", constant_json(y.constant)},
                              {"ratio", number_or_null(c.constant.ratio)}, {"change", number_or_null(c.constant.ratio - 1.0)},
                              {"agree", c.constant.agree}, {"text", c.constant.text}}},
          {"agree", c.agree()}};
}

std::string level_rows(const RecordedStudy& a, const RecordedStudy& b, std::size_t v) {
  std::string text = printf_string("%5s %10s %7s   %-11s %-11s %-8s %7s %7s\n", "level", "dt", "steps", "error A",
                                   "error B", "B/A", "order A", "order B");
  const RecordedVariable &x = a.variables[v], &y = b.variables[v];
  for (std::size_t k = 0; k < a.dt.size(); ++k)
    text += printf_string("%5zu %10.3e %7ld   %-11.4e %-11.4e %-8.4f %7s %7s\n", k, a.dt[k], a.steps[k], x.error[k],
                          y.error[k], y.error[k] / x.error[k], optional_text(x.pairwise[k], "%.3f").c_str(),
                          optional_text(y.pairwise[k], "%.3f").c_str());
  return text;
}

}  // namespace

StudyComparison compare_studies(const RecordedStudy& a, const RecordedStudy& b, const ComparisonTolerances& tolerances) {
  const std::string difference = study_difference(a, b);
  if (!difference.empty())
    throw InputError(printable(b.source) + " is not a result of the study of " + printable(a.source) + ": " + difference);
  StudyComparison comparison;
  comparison.tolerances = tolerances;
  for (std::size_t v = 0; v < a.variables.size(); ++v) {
    comparison.variables.push_back(compare_variable(a.variables[v], b.variables[v], tolerances));
    comparison.agree = comparison.agree && comparison.variables.back().agree();
  }
  return comparison;
}

std::string format_comparison(const RecordedStudy& a, const RecordedStudy& b, const StudyComparison& comparison) {
  const nlohmann::json& id = a.identity;
  const auto plain = [](const nlohmann::json& x) { return printable(x.is_string() ? x.get<std::string>() : x.dump()); };
  std::string text = "A " + printable(a.source) + ": integrator " + printable(a.integrator) + "\n";
  text += "B " + printable(b.source) + ": integrator " + printable(b.integrator) + "\n";
  text += "the same study: case " + plain(id["case"]) + ", reference " + plain(id["reference"]) + ", " +
          plain(id["particles"]) + " members, t_end " + plain(id["t_end"]) + ", ratio " + plain(id["ratio"]) +
          ", " + std::to_string(a.dt.size()) + " levels\n";
  for (std::size_t v = 0; v < comparison.variables.size(); ++v) {
    const VariableComparison& c = comparison.variables[v];
    text += "\n" + c.name + "\n" + level_rows(a, b, v);
    text += "  " + c.order_text + "\n  " + c.constant.text + "\n";
  }
  std::string differ;
  for (const std::string& line : disagreements(comparison)) differ += (differ.empty() ? "" : "; ") + line;
  text += comparison.agree ? printf_string("\nAGREE: every fitted order within %g and every error constant within %g%%\n",
                                           comparison.tolerances.order, 100.0 * comparison.tolerances.constant)
                           : "\nDIFFER: " + differ + "\n";
  return text;
}

nlohmann::json comparison_json(const RecordedStudy& a, const RecordedStudy& b, const StudyComparison& comparison) {
  using nlohmann::json;
  json variables = json::object();
  for (std::size_t v = 0; v < comparison.variables.size(); ++v)
    variables[comparison.variables[v].name] = variable_json(a, b, v, comparison.variables[v]);
  return {{"a", {{"file", a.source}, {"integrator", a.integrator}}},
          {"b", {{"file", b.source}, {"integrator", b.integrator}}},
          {"study", a.identity},
          {"levels", a.dt.size()},
          {"tolerances", {{"order", comparison.tolerances.order}, {"constant", comparison.tolerances.constant}}},
          {"variables", variables},
          {"agree", comparison.agree},
          {"verdict", comparison.agree ? "AGREE" : "DIFFER"},
          {"disagreements", disagreements(comparison)}};
}

}  // namespace dlpverify
