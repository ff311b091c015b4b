#include "integrators/catalog.hpp"

#include <iostream>
#include <sstream>

#include <sys/stat.h>

#include "dlpverify/errors.hpp"
#include "exchange/exchange_file.hpp"
#include "integrators/implicit/integrators.hpp"
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

IntegratorEntry by_name(IntegratorInfo info) { return {std::move(info), {}, {}, {}}; }

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
      {}};
  return entry;
}

IntegratorEntry tableau_entry() {
  return {{"tableau:FILE", 0, "your own explicit Butcher tableau from a TOML file, at the file's order (dlpverify tableau FILE)",
           runge_kutta_traits(), true},
          [](const std::string& path, const IntegratorContext&) { return make_tableau_integrator(path, std::cerr); },
          [](const std::string& path) {
            return path.empty() ? std::vector<ArgumentFile>{} : std::vector<ArgumentFile>{{"tableau file", path}};
          },
          {}};
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
  catalog.add_sweep(by_name({"arkode-adaptive:TABLE", 0, "an ARKODE table with an embedding, at the table's order",
                             sundials_adaptive_traits(false), true}));
  return catalog;
}

}  // namespace dlpverify
