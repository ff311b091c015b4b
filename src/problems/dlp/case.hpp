// A verification case: which terms of the DLP model are on, what it is compared with, and the
// study defaults (t_end, Δt, levels) under which its expected order shows.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/case_report.hpp"
#include "problems/dlp/exact/cloud_solution.hpp"
#include "problems/dlp/parameters.hpp"

namespace dlpverify::dlp {

struct CaseDefaults {
  double t_end;  // duration after t0 [s]
  double dt;     // coarsest step [s]
  int levels;
};

// The particles a case's diagnostics are reduced from: the launch cloud and the finest level's
// state of the same particles (a rank's share under mpirun).
struct DiagnosticsInput {
  const Physics& physics;
  const Launch& launch;
  const Cloud& initial;
  const Cloud& finest;
  double t_end;
};

// What a case reports besides errors (branch counts, invariants), as reductions over the particles
// (CaseReport): how each quantity combines, each particle's terms (a row per particle, a column
// per quantity), and the report from the quantities reduced over every particle.
struct CaseDiagnostics {
  std::vector<MemberReduction> reductions;
  Eigen::ArrayXXd (*terms)(const DiagnosticsInput& particles);
  nlohmann::json (*report)(const Physics& physics, const Launch& launch, const std::vector<double>& reduced,
                           double t_end);
};

struct Case {
  std::string name;
  std::string summary;
  Terms terms;
  exact::ParticleSolution solution;  // the closed form of docs/model.md §4; nullptr: none, CVODE is the reference
  std::string reference_detail;      // where the closed form comes from, or why there is none
  CaseDefaults defaults;
  bool z_axis_only = false;             // the cloud's particles on the z axis only
  const CaseDiagnostics* diagnostics = nullptr;  // nullptr: none
};

const std::vector<Case>& all_cases();

// The case of that name; throws InputError naming the case otherwise.
const Case& find_case(const std::string& name);

// "drag (constant C_D), gravity" …: the terms a case switches on, for `dlpverify cases`.
std::string describe_terms(const Terms& terms);

}  // namespace dlpverify::dlp
