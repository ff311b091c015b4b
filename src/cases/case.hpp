// A verification case: which terms of the DLP model are on, what it is compared with, and the
// study defaults (t_end, Δt, levels) under which its expected order shows.
#pragma once

#include <string>
#include <vector>

#include "exact/cloud_solution.hpp"
#include "model/parameters.hpp"

namespace dlpverify {

struct CaseDefaults {
  double t_end;  // duration after t0 [s]
  double dt;     // coarsest step [s]
  int levels;
};

struct Case {
  std::string name;
  std::string summary;
  Terms terms;
  exact::ParticleSolution solution;  // the closed form of SPEC §4; nullptr: none, CVODE is the reference
  std::string reference_detail;      // where the closed form comes from, or why there is none
  CaseDefaults defaults;
};

const std::vector<Case>& all_cases();

// The case of that name; throws InputError naming --case otherwise.
const Case& find_case(const std::string& name);

// "drag (constant C_D), gravity" …: the terms a case switches on, for `dlpverify cases`.
std::string describe_terms(const Terms& terms);

}  // namespace dlpverify
