// The public face of the references (dlpverify/reference.hpp): each question is put to the source
// of the settings' kind (references/source.hpp).
#include "dlpverify/reference.hpp"

#include <cmath>
#include <string>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "references/source.hpp"

namespace dlpverify {

namespace {

std::unique_ptr<references::ReferenceSource> source_of(const ReferenceSettings& settings) {
  switch (settings.kind) {
    case ReferenceKind::exact:
    case ReferenceKind::manufactured: return references::closed_form_source(settings.kind);
    case ReferenceKind::cvode: return references::cvode_source(settings);
    case ReferenceKind::integrator: return references::integrator_source(settings);
    case ReferenceKind::extended: return references::extended_source();
  }
  throw InputError("reference", std::to_string(static_cast<int>(settings.kind)), "is no reference kind");
}

}  // namespace

const char* reference_kind_name(ReferenceKind kind) {
  switch (kind) {
    case ReferenceKind::exact: return "exact";
    case ReferenceKind::cvode: return "cvode";
    case ReferenceKind::integrator: return "integrator";
    case ReferenceKind::manufactured: return "manufactured";
    case ReferenceKind::extended: return "extended";
  }
  return "unknown";
}

void check_reference_settings(const ReferenceSettings& settings) {
  if (!std::isfinite(settings.rtol) || settings.rtol < kTightestReferenceRtol || settings.rtol >= 1e-3)
    throw InputError("reference relative tolerance", value_text(settings.rtol), "must lie in [1e-14, 1e-3)");
  if (settings.max_steps < 1 || settings.max_steps > kMostCvodeSteps)
    throw InputError("CVODE step limit", std::to_string(settings.max_steps), "must lie in [1, 1e9]");
}

std::optional<ReferenceSettings> tightened_reference(const ReferenceSettings& settings, double ratio) {
  return source_of(settings)->tightened(ratio);
}

Reference compute_reference(const Problem& problem, const ReferenceSettings& settings, const State& initial,
                            double t_end, const std::vector<Variable>& variables) {
  return source_of(settings)->compute(problem, initial, t_end, variables);
}

std::function<State(double tau)> reference_trajectory(const Problem& problem, const ReferenceSettings& settings,
                                                      const State& initial) {
  return source_of(settings)->trajectory(problem, initial);
}

}  // namespace dlpverify
