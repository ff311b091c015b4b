#include "integrators/tableau/sharpness_report.hpp"

#include <cmath>

#include "io/format.hpp"
#include "io/printable.hpp"

namespace dlpverify {

namespace {

using nlohmann::json;

std::string coefficient_value(double x) { return printf_string("%.6g", x); }

// "2.03,2.01" or "none"; the study's figures for one column.
std::string figures(const std::vector<std::optional<double>>& values, const char* format) {
  std::string text;
  for (const auto& x : values) {
    if (!text.empty()) text += ',';
    text += x ? printf_string(format, *x) : std::string("none");
  }
  return text;
}
std::vector<std::optional<double>> finite(const std::vector<double>& values) {
  std::vector<std::optional<double>> out;
  for (double x : values) out.push_back(std::isfinite(x) ? std::optional<double>(x) : std::nullopt);
  return out;
}

std::string catch_cell(bool caught, const std::string& figures_text) {
  return std::string(caught ? "CAUGHT " : "missed ") + "(" + figures_text + ")";
}

// Which checks caught a mutant, by name.
std::vector<std::string> caught_by(const MutationVerdict& m, const std::string& alternative) {
  std::vector<std::string> by;
  if (m.caught_by_conditions()) by.push_back("conditions");
  if (m.study.order) by.push_back("order");
  if (m.study.constant) by.push_back("constant");
  if (m.alternative && m.alternative->order) by.push_back(alternative + " order");
  if (m.alternative && m.alternative->constant) by.push_back(alternative + " constant");
  return by;
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
  return text.empty() ? "NOTHING" : text;
}

std::string format_report(const RuntimeTableau& tableau, const SharpnessReport& r, const std::string& case_name,
                          const std::string& reference, const std::string& alternative) {
  std::string text = printf_string("sharpness of tableau %s (%s, order %d): delta = %g relative, a zero coefficient moved to %g\n",
                                   printable(tableau.source).c_str(), printable(tableau.name).c_str(), tableau.order,
                                   r.settings.delta, r.settings.delta);
  text += "study: case " + case_name + " against " + reference + "; order within " + printf_string("%g", r.settings.order_tolerance) +
          ", error constant within " + printf_string("%g%%", 100.0 * r.settings.constant_tolerance) + " of the unperturbed";
  text += alternative == "none" ? "\n" : "; a perturbation it misses is tried against " + alternative + "\n";
  std::vector<std::optional<double>> constants;
  for (const OrderAnalysis& a : r.unperturbed.orders)
    constants.push_back(a.constant.valid ? std::optional<double>(a.constant.value) : std::nullopt);
  std::string names;
  for (const Variable& v : r.unperturbed.plan.variables) names += (names.empty() ? "" : ",") + v.name;
  std::vector<std::optional<double>> orders;
  for (const OrderAnalysis& a : r.unperturbed.orders) orders.push_back(a.fit.valid ? std::optional<double>(a.fit.value) : std::nullopt);
  text += "unperturbed (" + names + "): fitted order " + figures(orders, "%.3f") + ", error constant " +
          figures(constants, "%.4e") + "\n\n";
  text += printf_string("%-11s %-12s %-12s %-11s %-24s %-28s %-36s %s\n", "coefficient", "was", "now", "conditions",
                        "order", "constant ratio", alternative == "none" ? "-" : alternative.c_str(), "caught by");
  for (const MutationVerdict& m : r.mutations) {
    const std::string alt = !m.alternative ? "-"
                            : catch_cell(m.alternative->caught(), figures(m.alternative->fitted_order, "%.3f") + "; " +
                                                                     figures(finite(m.alternative->constant_ratio), "%.4f"));
    text += printf_string("%-11s %-12s %-12s %-11s %-24s %-28s %-36s %s\n", m.mutation.coefficient.c_str(),
                          coefficient_value(m.mutation.original).c_str(),
                          (coefficient_value(m.mutation.perturbed) + (m.mutation.absolute ? " abs" : "")).c_str(),
                          m.caught_by_conditions() ? "CAUGHT" : "missed",
                          catch_cell(m.study.order, figures(m.study.fitted_order, "%.3f")).c_str(),
                          catch_cell(m.study.constant, figures(finite(m.study.constant_ratio), "%.4f")).c_str(), alt.c_str(),
                          joined(caught_by(m, alternative)).c_str());
  }
  text += "\n";
  for (const MutationVerdict& m : r.mutations)
    if (m.caught_by_conditions()) text += "  " + m.mutation.coefficient + ": " + printable(m.condition, 300) + "\n";
  const int total = static_cast<int>(r.mutations.size());
  text += printf_string("\ncaught by the study on %s: %d of %d; by some check: %d of %d\n", case_name.c_str(),
                        r.caught_by_study(), total, r.caught(), total);
  return text;
}

json catch_json(const StudyCatch& c) {
  json fitted = json::object(), ratio = json::object();
  for (std::size_t v = 0; v < c.variables.size(); ++v) {
    fitted[c.variables[v]] = c.fitted_order[v] ? json(*c.fitted_order[v]) : json();
    ratio[c.variables[v]] = number_or_null(c.constant_ratio[v]);
  }
  return {{"caught_by_order", c.order}, {"caught_by_constant", c.constant}, {"fitted_order", fitted}, {"constant_ratio", ratio}};
}

json report_json(const RuntimeTableau& tableau, const SharpnessReport& r, const std::string& case_name,
                 const std::string& reference, const std::string& alternative) {
  json mutations = json::array();
  for (const MutationVerdict& m : r.mutations)
    mutations.push_back({{"coefficient", m.mutation.coefficient},
                         {"original", m.mutation.original},
                         {"perturbed", m.mutation.perturbed},
                         {"absolute", m.mutation.absolute},
                         {"conditions", {{"caught", m.caught_by_conditions()}, {"condition", m.condition}}},
                         {"study", catch_json(m.study)},
                         {"alternative", m.alternative ? catch_json(*m.alternative) : json()},
                         {"caught_by", caught_by(m, alternative)},
                         {"caught", m.caught()}});
  return {{"tableau", tableau.name},       {"file", tableau.source},          {"order", tableau.order},
          {"delta", r.settings.delta},     {"case", case_name},               {"reference", reference},
          {"alternative_reference", alternative}, {"mutations", mutations},
          {"caught_by_study", r.caught_by_study()}, {"caught", r.caught()},
          {"total", r.mutations.size()}};
}

}  // namespace

SharpnessOutcome judge_sharpness(const RuntimeTableau& tableau, const SharpnessReport& report,
                                 const std::string& case_name, const std::string& reference,
                                 const std::string& alternative) {
  SharpnessOutcome outcome;
  outcome.unperturbed = check_orders(report.unperturbed, tableau.order, report.settings.order_tolerance);
  if (!outcome.unperturbed.passed()) {
    outcome.table = "the tableau as written fails its own check on case " + case_name + ":\n";
    for (const std::string& line : outcome.unperturbed.lines()) outcome.table += "  " + line + "\n";
    outcome.table += "nothing to measure: perturbations are judged against a study that passes\n";
    outcome.report = {{"tableau", tableau.name}, {"file", tableau.source}, {"unperturbed_findings", outcome.unperturbed.lines()}};
  } else {
    outcome.table = format_report(tableau, report, case_name, reference, alternative);
    outcome.report = report_json(tableau, report, case_name, reference, alternative);
  }
  outcome.report["unperturbed_passes"] = outcome.unperturbed.passed();
  outcome.passed = outcome.unperturbed.passed() && report.caught() == static_cast<int>(report.mutations.size());
  return outcome;
}

}  // namespace dlpverify
