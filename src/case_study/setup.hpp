// What converge, check and precision share: options → case (its defaults filled in) → problem,
// levels and reference, all validated before any work is done or any file exists.
#pragma once

#include <memory>

#include "case_study/options.hpp"
#include "integrators/registry.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"

namespace dlpverify::case_study {

struct StudySetup {
  std::unique_ptr<Problem> problem;
  StudyPlan plan;  // levels and measured variables; expected_order is the caller's
  ReferenceSettings reference;
};

// How many copies of the N × F state a study holds at its peak. Measured (/usr/bin/time -v, drag,
// R_out 40, 60 and 100, 17.1, 57.9 and 268 MB a copy): 3.1 for the harness's own Runge–Kutta
// methods (the measured reference, the previous and the current level; the lattice is rebuilt
// when needed, states are moved into measurement), counted as 4; 14.6–25.4 for SUNDIALS integrating the whole cloud (ARKODE
// Heun–Euler … CVODE BDF with SPGMR; precision runs both CVODE methods: 23.4; a diagonally implicit
// tableau through ARKStep, Crouzeix's SDIRK 4 at R_out 40: 25.5), and `stage_vectors` more for a
// diagonally implicit tableau's stages (IntegratorTraits); --per-particle adds 0.8, --history 1.9.
int state_copies(bool sundials_whole_cloud, bool history, bool per_particle, int stage_vectors = 0);

// Refuses --reference manufactured for an integrator whose `traits` say it does not call the
// problem's right-hand side (it would never see the source term): InputError naming --reference.
void check_manufactured_integrator(const ReferenceOptions& reference, const std::string& integrator,
                                   const IntegratorTraits& traits);

// Refuses an output path that cannot be written (--plot: not a figure's extension), before any work:
// InputError naming the option, OutputError for an unwritable folder.
void check_outputs(const std::vector<std::pair<std::string, std::string>>& outputs);

// Fills the case's defaults into already validated options (so reports show what was run),
// refuses a duration the problem cannot take, a step count that is not whole, an output that
// cannot be written, a study whose `state_copies` of the state do not fit in the available
// memory (naming --outer or --parcels, with the estimate and what is available), and a closed
// form whose audit fails on these parameters (docs/model.md §4), all before the problem is built;
// then builds the problem (wrapped with its manufactured source for --reference manufactured).
// Throws InputError naming the option and its value (OutputError for an unwritable output).
// `exec`: how an `exec:` program named by --reference integrator:exec:COMMAND@DT is run (shell,
// declared order, timeout, threads), as for --integrator.
StudySetup resolve_setup(ProblemOptions& problem, LevelOptions& levels, ReferenceOptions& reference,
                         const SolverOptions& solver, const std::vector<std::pair<std::string, std::string>>& outputs,
                         int state_copies, const exchange::ExecSettings& exec = {});

}  // namespace dlpverify::case_study
