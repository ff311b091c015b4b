// The problems and integrators the command line offers: every family's options bound to a command,
// and the names of the families' questions (src/families) and of the integrators a study can name
// (families/study_integrators.hpp).
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
#include "families/study_integrators.hpp"
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

using families::find_integrator_traits;
using families::integrator_traits;
using families::known_study_integrators;
using families::make_study_integrator;
using families::study_catalog;

}  // namespace dlpverify::cli
