// A verification case: which terms of the DLP model are on, what it is compared with, and the
// study defaults (t_end, Δt, levels) under which its expected order shows.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "problems/dlp/exact/cloud_solution.hpp"
#include "problems/dlp/parameters.hpp"

namespace dlpverify::dlp {

struct CaseDefaults {
  double t_end;  // duration after t0 [s]
  double dt;     // coarsest step [s]
  int levels;
};

// What a case reports besides errors (branch counts, invariants), from the launch cloud and the
// finest level's state; an empty object when it has nothing to add.
struct DiagnosticsInput {
  const Physics& physics;
  const Launch& launch;
  const Cloud& initial;
  const Cloud& finest;
  double t_end;
};
using CaseDiagnostics = nlohmann::json (*)(const DiagnosticsInput&);

struct Case {
  std::string name;
  std::string summary;
  Terms terms;
  exact::ParticleSolution solution;  // the closed form of docs/model.md §4; nullptr: none, CVODE is the reference
  std::string reference_detail;      // where the closed form comes from, or why there is none
  CaseDefaults defaults;
  bool z_axis_only = false;             // the cloud's particles on the z axis only
  CaseDiagnostics diagnostics = nullptr;
};

const std::vector<Case>& all_cases();

// The case of that name; throws InputError naming the case otherwise.
const Case& find_case(const std::string& name);

// "drag (constant C_D), gravity" …: the terms a case switches on, for `dlpverify cases`.
std::string describe_terms(const Terms& terms);

}  // namespace dlpverify::dlp
