// Reports of a finished study: a console table in the manner of deal.II's ConvergenceTable, CSV
// and JSON. Reports only format what the study computed; they never recompute anything.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/check.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify {

// What was studied, for the report's header.
struct StudyDescription {
  std::string case_name;
  std::string integrator;
  int integrator_order = 0;
  std::string reference;         // "exact" or "cvode"
  std::string reference_detail;  // which closed form, or the reference solver's settings
  long long particles = 0;
  double t0 = 0.0;
  nlohmann::json reference_statistics = nlohmann::json::object();  // the reference solve's counts
  nlohmann::json diagnostics = nlohmann::json::object();  // the case's own (branch counts, invariants)
  nlohmann::json options = nlohmann::json::object();     // every option with its value
  nlohmann::json provenance = nlohmann::json::object();  // build, host, date, command line
};

std::string format_table(const StudyDescription& description, const StudyResult& study,
                         const std::optional<CheckVerdict>& verdict);
std::string format_csv(const StudyDescription& description, const StudyResult& study);
nlohmann::json to_json(const StudyDescription& description, const StudyResult& study,
                       const std::optional<CheckVerdict>& verdict);

// The finest level's error of every particle against the reference, beside its similarity
// coordinate ξ at launch: CSV `particle,xi,err_position,err_velocity[,err_temperature][,err_mass]`.
std::string format_per_particle(const StudyResult& study, const State& reference, const Eigen::ArrayXd& xi);

}  // namespace dlpverify
