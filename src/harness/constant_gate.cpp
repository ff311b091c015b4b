#include "harness/constant_gate.hpp"

#include <cmath>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"

namespace dlpverify {

namespace {

// Why a variable has no constant: exact, or no level in the asymptotic range.
std::string no_constant(const RecordedVariable& v) {
  return v.exact_to_round_off ? "exact to round-off, no error constant" : "no error constant (no level in the asymptotic range)";
}

}  // namespace

ConstantComparison compare_constants(const RecordedVariable& base, const RecordedVariable& now, double tolerance) {
  ConstantComparison c;
  c.ratio = std::nan("");
  if (!base.constant && !now.constant) {
    c.agree = base.exact_to_round_off && now.exact_to_round_off;
    c.text = c.agree ? "exact to round-off in both: no error constant" : "no error constant in either";
    return c;
  }
  if (!base.constant || !now.constant) {
    c.text = !now.constant ? no_constant(now) + ", but the baseline has " + printf_string("%.4e", base.constant->value)
                           : printf_string("error constant %.4e, but the baseline has ", now.constant->value) + no_constant(base);
    return c;
  }
  const RecordedConstant &b = *base.constant, &n = *now.constant;
  if (b.order != n.order) {
    c.text = printf_string("error constants at order %g here and %g in the baseline: not comparable", n.order, b.order);
    return c;
  }
  c.ratio = n.value / b.value;
  c.agree = std::abs(n.value - b.value) <= tolerance * std::abs(b.value);
  c.text = printf_string("error constant %.4e %s %.4e +/- %g%% (band [%.4e, %.4e], ratio %.4f)", n.value,
                         c.agree ? "within" : "outside", b.value, 100.0 * tolerance, b.value * (1.0 - tolerance),
                         b.value * (1.0 + tolerance), c.ratio);
  if (n.levels != b.levels) c.text += "; fitted over levels " + levels_text(n.levels) + ", " + levels_text(b.levels) + " in the baseline";
  return c;
}

void require_baseline_of(const RecordedStudy& now, const RecordedStudy& baseline, double expected_order,
                         const std::map<std::string, double>& by_variable, const std::string& quantity) {
  const std::string difference = study_difference(now, baseline);
  if (!difference.empty()) throw InputError(quantity, baseline.source, "is not a baseline of this study: " + difference);
  for (const RecordedVariable& v : baseline.variables) {
    const auto own = by_variable.find(v.name);
    const double expected = own != by_variable.end() ? own->second : expected_order;
    if (v.constant && v.constant->order != expected)
      throw InputError(quantity, baseline.source,
                       "its error constants are fitted at order " + printf_string("%g", v.constant->order) +
                           ", this check expects order " + printf_string("%g", expected) +
                           (own != by_variable.end() ? " for " + v.name : ""));
  }
}

void check_constants(const RecordedStudy& now, const RecordedStudy& baseline, double tolerance, CheckVerdict& verdict) {
  for (std::size_t v = 0; v < now.variables.size() && v < baseline.variables.size(); ++v) {
    const ConstantComparison c = compare_constants(baseline.variables[v], now.variables[v], tolerance);
    verdict.findings.push_back({v, now.variables[v].name, Criterion::error_constant,
                                c.agree ? CheckOutcome::constant_within : CheckOutcome::constant_outside,
                                (c.agree ? "pass, " : "FAIL, ") + c.text});
  }
}

}  // namespace dlpverify
