// The problems and integrators the command line offers: every family's options bound to a command
// (the families themselves are src/families), and the integrators a study can name, each family's
// own schemes among them.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/options.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"
#include "integrators/exec/exec_integrator.hpp"
#include "families/families.hpp"
#include "integrators/catalog.hpp"
#include "integrators/registry.hpp"

namespace dlpverify::cli {

using families::CaseEntry;
using families::ProblemSize;
using families::all_cases;
using families::audit_all;
using families::audit_case;
using families::case_has_closed_form;
using families::check_duration;
using families::check_problem_options;
using families::fill_case_defaults;
using families::find_case_entry;
using families::make_problem;
using families::problem_of_case;
using families::problem_options_json;
using families::problem_size;
using families::validate_problem_options;

// Binds every family's options to a study command.
void add_problem_options(CLI::App& app, ProblemOptions& options);

// Every integrator: the explicit and SUNDIALS ones, the implicit ones, each family's own, then
// exec:COMMAND.
std::vector<IntegratorInfo> known_study_integrators();

// Every integrator a study can name (integrators/catalog.hpp), each family's own schemes included.
const IntegratorCatalog& study_catalog();

// The traits of the entry of study_catalog() that `spec` names (a pattern entry's prefix for
// exec:COMMAND and tableau:FILE); nullopt, or InputError naming --integrator, for none.
std::optional<IntegratorTraits> find_integrator_traits(const std::string& spec);
IntegratorTraits integrator_traits(const std::string& spec);
// The integrator of that name for a study of `case_name`; throws InputError naming --integrator
// for an unknown one, or a problem's own integrator given with another problem's case. `exec`
// configures an exec:COMMAND integrator (its command is the name's rest).
std::unique_ptr<Integrator> make_study_integrator(const std::string& name, const CvodeSettings& cvode,
                                                  const std::string& case_name,
                                                  const exchange::ExecSettings& exec = {});

}  // namespace dlpverify::cli
