#include "cli/idle_options.hpp"

#include <initializer_list>
#include <string>

#include "cli/command_line.hpp"
#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"

namespace dlpverify::cli {

namespace {

// Refuses each option of `names` that `command` was given (typed or from the study file) when
// `idle` holds, naming its last value and `why`.
void refuse_when(const CLI::App& command, bool idle, std::initializer_list<const char*> names, const std::string& why) {
  if (!idle) return;
  for (const char* name : names) {
    const CLI::Option* option = command.get_option_no_throw(name);
    if (option == nullptr || option->count() == 0) continue;
    const std::string value = option->results().empty() ? "" : option->results().back();  // a flag's: true or false
    throw InputError(name, value, why);
  }
}

// An unknown integrator has no traits: it is refused by name later, where the study makes it.
IntegratorTraits traits_of(const std::string& spec) { return find_integrator_traits(spec).value_or(IntegratorTraits{}); }

// The outputs of converge, check, precision and analyze: a title and a relative scale are the figure's.
void refuse_idle_output_options(const CLI::App& command, const OutputOptions& outputs) {
  refuse_when(command, outputs.plot_file.empty(), {"--title", "--plot-relative"}, "does nothing without --plot");
}

void refuse_idle_study_options(const CLI::App& command, const ConvergeOptions& o) {
  refuse_idle_output_options(command, o.outputs);
  const bool by_tolerance = o.tolerances.range.has_value();
  refuse_when(command, by_tolerance && !o.levels.auto_levels, {"--levels"},
              "does nothing in a study by --tolerances, which has no levels");
  refuse_when(command, !o.levels.auto_levels, {"--budget", "--order-ci"},
              "does nothing without --levels auto (it bounds the level search)");
  refuse_when(command, !by_tolerance, {"--tolerances-per-decade"}, "does nothing without --tolerances");
  const std::optional<IntegratorReferenceOption> by_integrator =
      o.reference.kind ? integrator_reference_option(*o.reference.kind) : std::nullopt;
  const bool exec = traits_of(o.integrator).runs_program || (by_integrator && traits_of(by_integrator->integrator).runs_program);
  refuse_when(command, !exec, {"--exec-order", "--exec-timeout", "--exec-shell"},
              "does nothing without an exec: program (--integrator exec:COMMAND, or --reference "
              "integrator:exec:COMMAND@DT)");
  // The method under test alone takes them: a reference runs at CvodeSettings' defaults and --reference-rtol.
  const bool cvode = traits_of(o.integrator).cvode_settings;
  refuse_when(command, !cvode && !by_tolerance, {"--rtol", "--atol", "--method"},
              "does nothing unless --integrator cvode (a CVODE reference takes --reference-rtol)");
  refuse_when(command, !cvode && by_tolerance, {"--method"}, "does nothing unless --integrator cvode");
  refuse_when(command, o.history_file.empty(), {"--history-outputs"}, "does nothing without --history");
  refuse_when(command, by_tolerance, {"--plot-relative"}, "does nothing in a study by --tolerances (its figure is error against rtol)");
  const bool extended = o.reference.precision == "extended";
  refuse_when(command, extended && by_tolerance, {"--precision"},
              "is for studies at levels: a sweep by --tolerances runs adaptive SUNDIALS methods, in double");
  refuse_when(command, extended && o.levels.auto_levels, {"--precision"},
              "runs fixed levels: the level search runs in double (give --levels N)");
}

// A work-precision sweep and a sharpness study run in double.
void refuse_extended(const CLI::App& command, const ReferenceOptions& o) {
  refuse_when(command, o.precision == "extended", {"--precision"}, "is for converge and check; this command runs in double");
}

void refuse_idle_check_options(const CLI::App& command, const CheckOptions& o) {
  refuse_idle_study_options(command, o);
  refuse_when(command, !o.tolerances.range, {"--expect-proportionality", "--proportionality-tolerance"},
              "does nothing without --tolerances (a study at levels is judged by --expect-order)");
  refuse_when(command, o.tolerances.range.has_value(),
              {"--expect-order", "--order-tolerance", "--baseline", "--constant-tolerance", "--no-escalate"},
              "does nothing in a study by --tolerances (judged by --expect-proportionality)");
}

// Without --adaptive each step sweeps to round-off: the adaptive run's settings have no run.
void refuse_idle_stagger_options(const CLI::App& command, const StaggerOptions& o) {
  refuse_when(command, !o.adaptive,
              {"--t-end", "--tol", "--block-tol", "--target-sweeps", "--exponent", "--dt-max", "--no-error-control"},
              "does nothing without --adaptive (each contraction step sweeps to round-off)");
}

void refuse_idle_compress_options(const CLI::App& command, const CompressOptions& o) {
  refuse_when(command, !o.bench, {"--bench-events"}, "does nothing without --bench");
}

}  // namespace

void refuse_idle_options(const CommandLine& line) {
  if (line.converge->parsed()) refuse_idle_study_options(*line.converge, line.converge_options);
  if (line.check->parsed()) refuse_idle_check_options(*line.check, line.check_options);
  if (line.stagger->parsed()) refuse_idle_stagger_options(*line.stagger, line.stagger_options);
  if (line.precision->parsed()) refuse_idle_output_options(*line.precision, line.precision_options.outputs);
  if (line.precision->parsed()) refuse_extended(*line.precision, line.precision_options.reference);
  if (line.sharpness->parsed()) refuse_extended(*line.sharpness, line.sharpness_options.reference);
  if (line.analyze->parsed()) refuse_idle_output_options(*line.analyze, line.analyze_options.outputs);
  if (line.compress->parsed()) refuse_idle_compress_options(*line.compress, line.compress_options);
}

}  // namespace dlpverify::cli
