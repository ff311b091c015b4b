// Every integrator a study can name, one entry each: its name (or a PREFIX:ARGUMENT pattern such
// as exec:COMMAND), order, summary and traits, how to make it, and the files its argument names.
// The one place that reads an integrator's name is IntegratorCatalog::find; every other decision
// reads the entry it returns.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dlpverify/integrator.hpp"
#include "dlpverify/tolerance_study.hpp"
#include "integrators/exec/exec_integrator.hpp"
#include "integrators/registry.hpp"

namespace dlpverify {

// What an entry may need to make its integrator: CVODE's settings (cvode), the program's settings
// (exec:COMMAND, whose command is the argument), and the absolute tolerance as asked, in units of
// each field's scale (none: rtol's); a sweep scales it with rtol, as atol / cvode.rtol × rtol.
struct IntegratorContext {
  CvodeSettings cvode;
  exchange::ExecSettings exec;
  std::optional<double> atol;
};

// A file an integrator's argument names: what it is ("tableau file", "program") and its path.
struct ArgumentFile {
  std::string what, path;
};

struct IntegratorEntry {
  IntegratorInfo info;
  // Makes the integrator of `argument` (empty for a plain name); null: a sweep's entry only, which
  // the study makes run by run (arkode-adaptive:TABLE).
  std::function<std::unique_ptr<Integrator>(const std::string& argument, const IntegratorContext&)> make;
  // The files the argument names, as the study reads them (empty: none).
  std::function<std::vector<ArgumentFile>(const std::string& argument)> argument_files;
  // The problem family whose cases alone it integrates (its title); empty: every problem.
  std::string family;
  // For a tolerance-driven entry (traits.tolerance_driven): the integrator of `argument` at any
  // rtol, for a sweep of tolerances. Throws InputError naming the "integrator" for an argument it
  // cannot sweep.
  std::function<SolveAtTolerance(const std::string& argument, const IntegratorContext&)> at_tolerance;
  // The traits of `argument` where they depend on it (a tableau file steps as a Runge–Kutta method
  // when explicit, through ARKStep's vectors when implicit); empty: info.traits for every argument.
  std::function<IntegratorTraits(const std::string& argument)> argument_traits;
};

class IntegratorCatalog {
 public:
  // Entries of a study at levels, listed in the order given.
  void add(IntegratorEntry entry) { levels_.push_back(std::move(entry)); }
  // Entries of a sweep of --tolerances only: arkode-adaptive:TABLE (adaptive_integrators() lists
  // the tables; cvode, which a study at levels runs too, is among the levels' entries).
  void add_sweep(IntegratorEntry entry) { sweep_.push_back(std::move(entry)); }

  struct Found {
    const IntegratorEntry* entry;
    std::string argument;  // what follows a pattern's prefix; empty for a plain name
  };
  // The entry `spec` names: a plain name exactly, or a pattern's prefix; a study's entries first,
  // then a sweep's. nullopt for none.
  std::optional<Found> find(const std::string& spec) const;

  const std::vector<IntegratorEntry>& levels() const { return levels_; }
  const std::vector<IntegratorEntry>& sweep() const { return sweep_; }

 private:
  std::vector<IntegratorEntry> levels_, sweep_;
};

// The library's integrators in the order `dlpverify cases` lists them: the explicit and SUNDIALS
// methods, the implicit ones, then `problem_schemes` (a problem family's own), exec:COMMAND and
// tableau:FILE; and the sweep's arkode-adaptive:TABLE.
IntegratorCatalog study_integrators(std::vector<IntegratorEntry> problem_schemes);

}  // namespace dlpverify
