// What converge, check and precision share: options → case (its defaults filled in) → cloud,
// physics, levels and reference, all validated before any work is done or any file exists.
#pragma once

#include "problems/dlp/case.hpp"
#include "sundials/reference.hpp"
#include "cli/options.hpp"
#include "harness/study.hpp"
#include "problems/dlp/cloud.hpp"

namespace dlpverify::cli {

struct StudySetup {
  const Case* test_case = nullptr;
  Physics physics;
  Lattice lattice;
  Launch launch;
  StudyPlan plan;  // levels and measured variables; expected_order is the caller's
  ReferenceSettings reference;
};

// Validates `options` for `command`, fills the case's defaults into them (so reports show what
// was run), refuses a duration past burn-out, a step count that is not whole, an output that
// cannot be written, and a closed form whose audit fails on these parameters (SPEC §4).
// Throws InputError naming the option and its value.
StudySetup resolve_setup(Options& options, Command command);

}  // namespace dlpverify::cli
