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
  std::string disagreements;
  for (std::size_t v = 0; v < comparison.variables.size(); ++v) {
    const VariableComparison& c = comparison.variables[v];
    text += "\n" + c.name + "\n" + level_rows(a, b, v);
    text += "  " + c.order_text + "\n  " + c.constant.text + "\n";
    if (!c.orders_agree) disagreements += (disagreements.empty() ? "" : "; ") + c.name + ": " + c.order_text;
    if (!c.constant.agree) disagreements += (disagreements.empty() ? "" : "; ") + c.name + ": " + c.constant.text;
  }
  text += comparison.agree ? printf_string("\nAGREE: every fitted order within %g and every error constant within %g%%\n",
                                           comparison.tolerances.order, 100.0 * comparison.tolerances.constant)
                           : "\nDIFFER: " + disagreements + "\n";
  return text;
}

}  // namespace dlpverify
