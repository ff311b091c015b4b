#include "integrators/tableau/sharpness.hpp"

#include <cmath>

#include "dlpverify/check.hpp"
#include "harness/constant_gate.hpp"
#include "dlpverify/recorded_study.hpp"
#include "integrators/tableau/order_conditions.hpp"
#include "integrators/tableau/tableau_integrator.hpp"
#include "io/format.hpp"

namespace dlpverify {

namespace {

TableauMutation mutate(const RuntimeTableau& tableau, const std::string& coefficient, double& x, double delta) {
  TableauMutation m;
  m.coefficient = coefficient;
  m.original = x;
  m.absolute = x == 0.0;
  m.perturbed = m.absolute ? delta : x * (1.0 + delta);
  const double kept = x;
  x = m.perturbed;
  m.tableau = tableau;
  x = kept;
  m.tableau.source = tableau.source + " with " + coefficient + " = " + printf_string("%.17g", m.perturbed);
  return m;
}

// The mutant's study beside the unperturbed one: its orders against the claim, its constants
// against the unperturbed constants.
StudyCatch judge(const StudyResult& mutant, const StudyResult& unperturbed, double claimed,
                 const SharpnessSettings& settings) {
  StudyCatch c;
  c.order = !check_orders(mutant, claimed, settings.order_tolerance).passed();
  const std::vector<RecordedVariable> now = recorded_variables(mutant), base = recorded_variables(unperturbed);
  for (std::size_t v = 0; v < now.size(); ++v) {
    const ConstantComparison constant = compare_constants(base[v], now[v], settings.constant_tolerance);
    c.constant = c.constant || !constant.agree;
    c.variables.push_back(now[v].name);
    c.fitted_order.push_back(now[v].order);
    c.constant_ratio.push_back(constant.ratio);
  }
  return c;
}

}  // namespace

std::vector<TableauMutation> tableau_mutations(const RuntimeTableau& tableau, double delta) {
  RuntimeTableau t = tableau;  // mutate() moves one coefficient of t and puts it back
  std::vector<TableauMutation> mutations;
  const int s = t.stages();
  for (int i = 1; i < s; ++i)
    for (int j = 0; j < i; ++j)
      mutations.push_back(mutate(t, "a_" + std::to_string(i + 1) + std::to_string(j + 1),
                                 t.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], delta));
  for (int i = 0; i < s; ++i) mutations.push_back(mutate(t, "b_" + std::to_string(i + 1), t.b[static_cast<std::size_t>(i)], delta));
  for (int i = 0; i < s; ++i) mutations.push_back(mutate(t, "c_" + std::to_string(i + 1), t.c[static_cast<std::size_t>(i)], delta));
  return mutations;
}

int SharpnessReport::caught_by_study() const {
  int n = 0;
  for (const MutationVerdict& m : mutations) n += m.study.caught() ? 1 : 0;
  return n;
}

int SharpnessReport::caught() const {
  int n = 0;
  for (const MutationVerdict& m : mutations) n += m.caught() ? 1 : 0;
  return n;
}

SharpnessReport measure_sharpness(const RuntimeTableau& tableau, const SharpnessSettings& settings,
                                  const IntegratorStudy& study, const IntegratorStudy& alternative) {
  SharpnessReport report;
  report.settings = settings;
  const double claimed = tableau.order;
  TableauIntegrator original(tableau);
  report.unperturbed = study(original);
  // Perturbations are judged against a study that passes: one that fails as written measures nothing.
  if (!check_orders(report.unperturbed, claimed, settings.order_tolerance).passed()) return report;
  for (TableauMutation& mutation : tableau_mutations(tableau, settings.delta)) {
    MutationVerdict verdict;
    const TableauCheck conditions = check_tableau(mutation.tableau);  // failed_claims() points into it
    const std::vector<const OrderCondition*> failed = conditions.failed_claims();
    if (!failed.empty()) verdict.condition = failed.front()->failure();
    TableauIntegrator mutant(mutation.tableau);
    verdict.study = judge(study(mutant), report.unperturbed, claimed, settings);
    if (!verdict.study.caught() && alternative) {
      if (!report.unperturbed_alternative) report.unperturbed_alternative = alternative(original);
      verdict.alternative = judge(alternative(mutant), *report.unperturbed_alternative, claimed, settings);
    }
    verdict.mutation = std::move(mutation);
    report.mutations.push_back(std::move(verdict));
  }
  return report;
}

}  // namespace dlpverify
