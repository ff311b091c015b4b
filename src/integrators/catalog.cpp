#include "integrators/catalog.hpp"

#include <iostream>
#include <sstream>

#include <sys/stat.h>

#include "dlpverify/errors.hpp"
#include "exchange/command_template.hpp"
#include "exchange/exchange_file.hpp"
#include "integrators/implicit/integrators.hpp"
#include "integrators/sundials/arkode_adaptive.hpp"
#include "integrators/tableau/tableau_integrator.hpp"

namespace dlpverify {

namespace {

// A word of a command that names an existing regular file (no placeholder in it).
bool names_a_file(const std::string& word) {
  struct stat st {};
  return word.find('{') == std::string::npos && ::stat(word.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// A word of a command with the shell's quotes around it taken off.
std::string unquoted(std::string word) {
  if (word.size() >= 2 && (word.front() == '\'' || word.front() == '"') && word.back() == word.front())
    word = word.substr(1, word.size() - 2);
  return word;
}

IntegratorEntry by_name(IntegratorInfo info) { return {std::move(info), {}, {}, {}, {}, {}}; }

// The absolute tolerances of a sweep's run at `rtol`: the asked atol scaled with rtol, per field.
std::vector<double> swept_atol(const Problem& problem, const State& initial, const IntegratorContext& context, double rtol) {
  return absolute_tolerances(problem, initial, context.atol ? *context.atol / context.cvode.rtol * rtol : rtol);
}

// CVODE over the whole duration in one solve, no step limit but the duration.
SolveAtTolerance cvode_at_tolerance(const IntegratorContext& context) {
  check_cvode_settings(context.cvode);  // its rtol scales an asked atol (swept_atol)
  return [context](const Problem& problem, State& state, double t0, double duration, double rtol,
                   SolverStatistics& statistics) {
    CvodeSettings settings = context.cvode;
    settings.rtol = rtol;
    settings.atol = swept_atol(problem, state, context, rtol);
    settings.max_step = duration;
    CvodeIntegrator integrator(settings);
    integrator.solve(problem, state, t0, t0 + duration);
    statistics = integrator.statistics();
  };
}

// arkode-adaptive:TABLE, a table with an embedding (checked when the sweep is made).
SolveAtTolerance arkode_at_tolerance(const std::string& table, const IntegratorContext& context) {
  check_arkode_adaptive_table(table);
  check_cvode_settings(context.cvode);  // its rtol and step limit, as CVODE's
  return [table, context](const Problem& problem, State& state, double t0, double duration, double rtol,
                          SolverStatistics& statistics) {
    const ArkodeAdaptiveSettings settings{table, rtol, swept_atol(problem, state, context, rtol), context.cvode.max_steps,
                                          context.cvode.across_ranks};
    solve_arkode_adaptive(problem, state, t0, t0 + duration, settings, statistics);
  };
}

// exec:COMMAND with {rtol}: the program run once over the whole duration, choosing its own steps;
// {atol} is the asked atol when given, else rtol (a number: the program scales it as it sees fit).
SolveAtTolerance program_at_tolerance(const std::string& command, const IntegratorContext& context) {
  if (command.find("{rtol}") == std::string::npos)
    throw InputError("integrator", exchange::kExecPrefix + command, "has no {rtol} placeholder: it cannot be given a tolerance");
  exchange::check_exec_settings(context.exec);
  return [command, context](const Problem& problem, State& state, double t0, double duration, double rtol,
                            SolverStatistics& statistics) {
    exchange::ExecSettings settings = context.exec;
    settings.command = exchange::fill_placeholders(
        command, {{"rtol", exchange::exact_text(rtol)}, {"atol", exchange::exact_text(context.atol.value_or(rtol))}});
    exchange::ExecIntegrator integrator(settings);
    integrator.advance(problem, state, t0, duration, 1);
    statistics = integrator.statistics();
  };
}

// exec:COMMAND: the user's program, which steps by its own equations and its own steps, swept by
// {rtol}; the words of the command that name files are its inputs.
IntegratorEntry program_entry() {
  IntegratorTraits program;
  program.calls_problem_rhs = false;
  program.tolerance_driven = true;
  program.runs_program = true;
  IntegratorEntry entry{
      {"exec:COMMAND", 0, "your own program, run per level on an HDF5 file (docs/exchange.md); --exec-order P", program, true},
      [](const std::string& command, const IntegratorContext& context) -> std::unique_ptr<Integrator> {
        exchange::ExecSettings settings = context.exec;
        settings.command = command;
        try {
          return std::make_unique<exchange::ExecIntegrator>(settings);
        } catch (const exchange::ExchangeError& e) {
          throw InputError("integrator", exchange::kExecPrefix + command, e.what());
        }
      },
      [](const std::string& command) {
        std::vector<ArgumentFile> files;
        std::istringstream words(command);
        for (std::string word; words >> word;)
          if (names_a_file(unquoted(word))) files.push_back({"program", unquoted(word)});
        return files;
      },
      {},
      program_at_tolerance,
      {}};
  return entry;
}

IntegratorEntry tableau_entry() {
  return {{"tableau:FILE", 0, "your own Butcher tableau from a TOML file, explicit or diagonally implicit, at the file's order (dlpverify tableau FILE)",
           runge_kutta_traits(), true},
          [](const std::string& path, const IntegratorContext&) { return make_tableau_integrator(path, std::cerr); },
          [](const std::string& path) {
            return path.empty() ? std::vector<ArgumentFile>{} : std::vector<ArgumentFile>{{"tableau file", path}};
          },
          {},
          {},
          [](const std::string& path) { return tableau_traits(read_tableau_file(path)); }};
}

}  // namespace

std::optional<IntegratorCatalog::Found> IntegratorCatalog::find(const std::string& spec) const {
  for (const std::vector<IntegratorEntry>* list : {&levels_, &sweep_})
    for (const IntegratorEntry& entry : *list) {
      const IntegratorInfo& info = entry.info;
      if (!info.pattern) {
        if (spec == info.name) return Found{&entry, ""};
        continue;
      }
      const std::string prefix = info.name.substr(0, info.name.find(':') + 1);
      if (spec.rfind(prefix, 0) == 0) return Found{&entry, spec.substr(prefix.size())};
    }
  return std::nullopt;
}

IntegratorCatalog study_integrators(std::vector<IntegratorEntry> problem_schemes) {
  IntegratorCatalog catalog;
  // The explicit and SUNDIALS methods, made by make_integrator (which also knows every
  // arkode-erk:TABLE by its table's name).
  for (IntegratorInfo& info : known_integrators()) {
    IntegratorEntry entry = by_name(std::move(info));
    const std::string name = entry.info.name;
    entry.make = [name](const std::string&, const IntegratorContext& context) { return make_integrator(name, context.cvode); };
    if (entry.info.traits.tolerance_driven)  // cvode, the one of them swept by tolerance too
      entry.at_tolerance = [](const std::string&, const IntegratorContext& context) { return cvode_at_tolerance(context); };
    catalog.add(std::move(entry));
  }
  for (IntegratorInfo& info : implicit::implicit_integrators()) {
    IntegratorEntry entry = by_name(std::move(info));
    const std::string name = entry.info.name;
    entry.make = [name](const std::string&, const IntegratorContext&) { return implicit::make_implicit_integrator(name); };
    catalog.add(std::move(entry));
  }
  for (IntegratorEntry& entry : problem_schemes) catalog.add(std::move(entry));
  catalog.add(program_entry());
  catalog.add(tableau_entry());
  // A sweep's own: arkode-adaptive:TABLE for any table, which the sweep checks (cvode is above).
  IntegratorEntry adaptive_table = by_name({"arkode-adaptive:TABLE", 0, "an ARKODE table with an embedding, at the table's order",
                                           sundials_adaptive_traits(false), true});
  adaptive_table.at_tolerance = arkode_at_tolerance;
  catalog.add_sweep(std::move(adaptive_table));
  return catalog;
}

}  // namespace dlpverify
