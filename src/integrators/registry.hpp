// The integrators a study can name, and how to make one.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/sundials/cvode_integrator.hpp"
#include "dlpverify/integrator.hpp"

namespace dlpverify {

// What a study must know of an integrator besides its name and order, declared by the entry that
// lists it (in the spirit of Boost.Odeint's stepper categories): every decision a study makes about
// an integrator — under mpirun, with a manufactured source, in a sweep of tolerances, for the memory
// estimate — reads these, never the name.
struct IntegratorTraits {
  // How it steps a population: each member alone, so a rank's share takes the serial run's bits
  // (the Runge–Kutta block steps); the whole population in vectors whose sums span every rank
  // (SUNDIALS over CvodeSettings::across_ranks); or the whole population at once, on one rank.
  using Reach = IntegratorReach;
  Reach reach = Reach::whole_population;
  bool calls_problem_rhs = true;  // steps by Problem::rhs, so a manufactured source reaches it
  bool tolerance_driven = false;  // can choose its steps to rtol and atol: a sweep of --tolerances
  bool cvode_settings = false;    // --rtol, --atol and --method set it
  bool state_vectors = false;     // keeps about 22 copies of the state in SUNDIALS vectors (memory)
  int stage_vectors = 0;          // and these more, growing with a diagonally implicit tableau's stages
  bool runs_program = false;      // a program of the user's (exec:): --exec-order, --exec-timeout apply
};

struct IntegratorInfo {
  std::string name;
  int order;  // 0: variable order
  std::string summary;
  IntegratorTraits traits;
  bool pattern = false;  // the name is PREFIX:ARGUMENT ("exec:COMMAND"), standing for every argument
};

// The traits of the integrators of known_integrators() and adaptive_integrators().
IntegratorTraits runge_kutta_traits();     // the built-in Runge–Kutta methods and tableau files
IntegratorTraits sundials_fixed_traits();  // arkode-erk:TABLE
IntegratorTraits sundials_adaptive_traits(bool cvode);  // cvode (true), arkode-adaptive:TABLE (false)

// The built-in explicit Runge–Kutta methods (rk2, euler, …: a tableau of
// include/dlpverify/runge_kutta.hpp and one row in registry.cpp each), in the order listed.
std::vector<std::string> runge_kutta_names();

// The built-in Runge–Kutta methods, cvode, and arkode-erk:TABLE for every ARKODE explicit table.
std::vector<IntegratorInfo> known_integrators();

// The integrators a study by --tolerances sweeps, which are not levels' integrators: cvode, and
// arkode-adaptive:TABLE for every ARKODE table with an embedding, explicit (ERK) and implicit
// (DIRK), at the table's order.
std::vector<IntegratorInfo> adaptive_integrators();

// Makes an integrator by name (`settings` apply to cvode). Throws InputError naming the
// integrator for an unknown one.
std::unique_ptr<Integrator> make_integrator(const std::string& name, const CvodeSettings& settings = {});

}  // namespace dlpverify
