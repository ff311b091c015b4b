#include "case_study/analyze.hpp"

#include <chrono>

#include "case_study/ci_report.hpp"
#include "case_study/html_report.hpp"
#include "case_study/inputs.hpp"
#include "case_study/outputs.hpp"
#include "case_study/setup.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/report.hpp"
#include "dlpverify/study.hpp"
#include "exchange/run_set.hpp"
#include "io/format.hpp"
#include "io/junit_xml.hpp"
#include "io/printable.hpp"
#include "io/provenance.hpp"
#include "io/value_checks.hpp"
#include "study/verdict.hpp"

namespace dlpverify::case_study {

namespace {

std::vector<std::pair<std::string, std::string>> output_files(const AnalyzeOptions& o) {
  return {{"--json", o.outputs.json_file}, {"--csv", o.outputs.csv_file}, {"--table", o.outputs.table_file},
          {"--plot", o.outputs.plot_file},      {"--junit", o.junit_file},     {"--html", o.html_file}};
}

void validate(const AnalyzeOptions& o) {
  for (double dt : o.dt) require_positive("--dt", dt);
  if (o.t_end) require_positive("--t-end", *o.t_end);
  if (o.order < 0 || o.order > 20) throw InputError("--order", std::to_string(o.order), "must lie in [0, 20]");
  if (!o.expect_order && !o.expect_order_by_variable.empty())
    throw InputError("--expect-order", o.expect_order_by_variable.begin()->first + "=" +
                                           value_text(o.expect_order_by_variable.begin()->second),
                     "a variable's own order needs P, the order of the others: give --expect-order P too");
  require_positive("--order-tolerance", o.order_tolerance);
  for (const auto& [option, path] : {std::pair<const char*, const std::string&>{"--junit", o.junit_file}, {"--html", o.html_file}})
    if (!path.empty() && !o.expect_order)
      throw InputError(option, path, "reports a verdict: give --expect-order");
  if (!o.variables.empty() && !o.variables_file.empty())
    throw InputError("--variable", o.variables.front(), "give the variables by --variable or by --variables, not both");
  validate_outputs(output_files(o), "");
}

nlohmann::json to_json(const AnalyzeOptions& o) {
  nlohmann::json j = outputs_json(o.outputs);
  j.update({{"runs", o.runs},
            {"reference", o.reference},
            {"reference-check", o.reference_check},
            {"dt", o.dt},
            {"t-end", optional_json(o.t_end)},
            {"variable", o.variables},
            {"variables", o.variables_file},
            {"order", o.order},
            {"expect-order", expected_orders_json(o.expect_order, o.expect_order_by_variable)},
            {"order-tolerance", o.order_tolerance},
            {"label", o.label},
            {"plot-relative", o.plot_relative},
            {"junit", o.junit_file},
            {"html", o.html_file}});
  return j;
}

exchange::RunRequest run_request(const AnalyzeOptions& o) {
  exchange::RunRequest request;
  request.paths = o.runs;
  request.reference = o.reference;
  request.reference_check = o.reference_check;
  request.dt = o.dt;
  request.duration = o.t_end;
  if (!o.variables_file.empty()) request.variables = exchange::read_variables_file(o.variables_file);
  for (const std::string& text : o.variables) request.variables.push_back(exchange::parse_variable(text));
  return request;
}

// The levels of the runs: Δt_0 = duration / n_0 and r = n_1 / n_0 (read_runs checked the rest).
StudyPlan run_plan(const exchange::RunSet& runs, const AnalyzeOptions& o) {
  StudyPlan plan;
  plan.t_end = runs.duration;
  plan.levels = static_cast<int>(runs.states.size());
  plan.coarsest_dt = runs.duration / static_cast<double>(runs.steps[0]);
  plan.ratio = static_cast<double>(runs.steps[1]) / static_cast<double>(runs.steps[0]);
  plan.expected_order = o.expect_order ? *o.expect_order : o.order;  // as check takes it
  plan.variables = runs.variables;
  plan.expected_order_by_variable = o.expect_order_by_variable;
  check_expected_orders(plan);  // each names a measured variable, before any output
  return plan;
}

std::string reference_detail(const exchange::RunSet& runs, const AnalyzeOptions& o) {
  const std::string members = runs.matched_by_id ? "members matched by id" : "members matched by position";
  if (!o.reference_check.empty())
    return "the file " + printable(o.reference, 200) + ", its error estimated against " + printable(o.reference_check, 200) +
           printf_string(" (half its step): the difference x %.6g; ", halved_step_error_factor(o.order)) + members;
  if (!o.reference.empty()) return "the file " + printable(o.reference, 200) + ", its error not estimated; " + members;
  return "none: each run measured against the next finer one (self-convergence); " + members;
}

// The reference's error per variable, by Richardson's rule against its run at half the step
// (as an integrator reference's is); zeros when there is none to estimate it with.
std::vector<double> reference_error(const exchange::RunSet& runs, const AnalyzeOptions& o) {
  if (!runs.reference_check) return std::vector<double>(runs.variables.size(), 0.0);
  return halved_step_error(*runs.reference, *runs.reference_check, runs.variables, o.order);
}

}  // namespace

CaseOutcome run_analysis(const AnalyzeOptions& options, const std::string& command_line) {
  const auto start = std::chrono::steady_clock::now();
  validate(options);
  std::vector<NamedPath> inputs;
  for (const std::string& run : options.runs) inputs.push_back({"run", run});
  for (const auto& [name, path] : {std::pair<std::string, std::string>{"--reference", options.reference},
                                   {"--reference-check", options.reference_check},
                                   {"--variables", options.variables_file}})
    if (!path.empty()) inputs.push_back({name, path});
  refuse_shared_files(inputs, named_paths(output_files(options)));
  check_outputs(output_files(options));
  const exchange::RunSet runs = exchange::read_runs(run_request(options));
  const StudyPlan plan = run_plan(runs, options);
  const StudyResult study =
      analyse_states(plan, runs.states, runs.reference ? &*runs.reference : nullptr, reference_error(runs, options));
  StudyDescription description;
  description.case_name = "analyze";
  description.integrator = options.label;
  description.integrator_order = options.order;
  description.reference = options.reference.empty() ? "next run" : "file";
  description.reference_detail = reference_detail(runs, options);
  description.particles = runs.states.front().rows();
  description.t0 = runs.t0;
  description.options = to_json(options);
  description.provenance = provenance(command_line);

  // The verdict and the report as a check's (study/verdict.hpp); runs made elsewhere have no level
  // search, no baseline and no problem to explain a missed order with.
  std::optional<CheckVerdict> verdict;
  if (options.expect_order)
    verdict = judge_study(description, study, *options.expect_order, options.order_tolerance, nullptr, nullptr, 0.0);
  const StudyReport report = study_report(description, study, verdict, nullptr, std::nullopt);

  CaseOutcome outcome(verdict ? verdict->exit_code() : kExitDone,
                      any_on_standard_output(output_files(options)) ? "" : report.table);
  if (verdict) outcome.verdicts = variable_verdicts(study, *verdict);
  outcome.table = report.table;
  outcome.report = report.result;
  outcome.study = options.label;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  OutputSet outputs;
  add_study_outputs(outputs, options.outputs, options.plot_relative, description, study, report.result, report.table);
  if (wanted(options.junit_file)) outputs.add(options.junit_file, junit_xml({junit_suite(outcome.study, outcome)}));
  if (wanted(options.html_file))
    outputs.add(options.html_file,
                html_report(outcome.study, {SuiteStudy{outcome.study, "", outcome, kExitDone, "", outcome.seconds}}));
  outputs.commit();
  return outcome;
}

}  // namespace dlpverify::case_study
