/// @file
/// Reports of a finished study: a console table in the manner of deal.II's ConvergenceTable, CSV
/// and JSON. Reports only format what the study computed; they never recompute anything.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/case_report.hpp"
#include "dlpverify/check.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

/// What was studied, for the report's header.
struct StudyDescription {
  std::string case_name;         ///< the problem's name(), e.g. "drag"
  std::string integrator;        ///< the integrator's name()
  int integrator_order = 0;      ///< its nominal order (0: variable order)
  std::string reference;         ///< "exact" or "cvode"
  std::string reference_detail;  ///< which closed form, or the reference solver's settings
  long long particles = 0;       ///< members N
  MemberNouns member_nouns;       ///< what the members are called: the problem's MemberNoun
  double t0 = 0.0;               ///< start time, in time_unit
  std::string time_unit = "s";   ///< of t0, t_end and Δt: the problem's step_unit ("1": dimensionless)
  nlohmann::json reference_statistics = nlohmann::json::object();  ///< the reference solve's counts
  nlohmann::json diagnostics = nlohmann::json::object();  ///< the case's own (branch counts, invariants)
  nlohmann::json parameters = nlohmann::json::object();   ///< the case's physical parameters (CaseReport::parameters)
  nlohmann::json options = nlohmann::json::object();     ///< every option with its value
  nlohmann::json provenance = nlohmann::json::object();  ///< build, host, date, command line
};

/// The console table: one row per level with Δt, steps, the norms, pairwise orders and statuses,
/// then the fitted orders, and the verdict when there is one.
std::string format_table(const StudyDescription& description, const StudyResult& study,
                         const std::optional<CheckVerdict>& verdict);
/// CSV of the levels under a `# dlpverify …` provenance header: `level,dt,steps,wall_s`, then
/// `l2_`, `rms_`, `rel_`, `max_`, `order_` and `status_` of each variable, then the level's `status`.
std::string format_csv(const StudyDescription& description, const StudyResult& study);
/// The whole study as JSON: the description (with `time_unit`), the measured variables in order
/// (`variables`) with their units (`units`: name → unit), every level, the order analyses, the
/// reference's trust and the verdict when there is one.
nlohmann::json to_json(const StudyDescription& description, const StudyResult& study,
                       const std::optional<CheckVerdict>& verdict);

/// What makes two studies comparable, as their JSON results record it: `case`, `reference`,
/// `particles`, `t0`, `t_end`, `ratio`, `variables` and `parameters` (the integrator is what may
/// differ). to_json writes these keys from here; a baseline gate compares them.
nlohmann::json study_identity(const StudyDescription& description, const StudyResult& study);

/// The finest level's error of every particle against the reference, beside its similarity
/// coordinate ξ at launch: CSV `particle,xi,err_<variable>…` (`err_position,err_velocity` for the
/// cloud), under a units line `# units: 1,1,<each variable's unit>…` when some variable's unit is
/// not the one its name implies (io/result_units.hpp).
std::string format_per_particle(const StudyResult& study, const State& reference, const Eigen::ArrayXd& xi);

}  // namespace dlpverify
