// The verdicts where a CI looks: each variable's verdict of a check, and the JUnit XML test suite
// of a study (one test case per variable: a failure carries its finding as the message, and the
// finding then the study's table as the text; an inconclusive one is skipped with the same text; a
// study that could not run is one error).
#pragma once

#include <string>
#include <vector>

#include "case_study/outcome.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/study.hpp"
#include "io/junit_xml.hpp"

namespace dlpverify::case_study {

// Each variable's verdict from a check's findings (each "NAME: …"; a variable may have several:
// its order, its reference's trust, its constant), in the order of `variables`, expecting
// verdict.expected_order (a sweep of --tolerances: its exponent) and with no fitted order.
std::vector<VariableVerdict> variable_verdicts(const std::vector<Variable>& variables, const CheckVerdict& verdict);
// The same for a study at levels: each variable's own expected order and its fitted order.
std::vector<VariableVerdict> variable_verdicts(const StudyResult& study, const CheckVerdict& verdict);

// What a CI report names a study by: its study file's name without the folder and .toml (`config`),
// else the case and the integrator ("drag rk2").
std::string study_name(const std::string& config, const std::string& case_name, const std::string& integrator);

// Each variable's numbers as a trend plugin reads them, named VARIABLE.order, .order_low and
// .order_high (the 95% interval, where the fit has one), .expected_order, .order_tolerance (the
// band is expected ± tolerance) and .error_constant (C of e ≈ C Δt^P); "exponent" in the place of
// "order" for a sweep of --tolerances. Printed to 6 significant digits; a number the study has not
// got (no fit, a NaN) is left out.
std::vector<JunitProperty> junit_properties(const std::vector<VariableVerdict>& verdicts);

// The test suite `name` of a study's outcome: one case per variable, classname `name`, and the
// variables' junit_properties.
JunitSuite junit_suite(const std::string& name, const CaseOutcome& outcome);

// The test suite of a study that ended without a verdict: one case "study" whose error is `line`
// (bad input, a solver's failure, an output not written), `code` its exit code.
JunitSuite junit_error_suite(const std::string& name, int code, const std::string& line, double seconds);

}  // namespace dlpverify::case_study
