// The integrators a study of a case can name: the catalogue of every method (integrators/catalog.hpp)
// with each family's own schemes, which refuse the other families' cases.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dlpverify/integrator.hpp"
#include "integrators/catalog.hpp"
#include "integrators/exec/exec_integrator.hpp"
#include "integrators/registry.hpp"
#include "integrators/sundials/cvode_integrator.hpp"

namespace dlpverify::families {

// Every integrator: the explicit and SUNDIALS ones, the implicit ones, each family's own, then
// exec:COMMAND.
std::vector<IntegratorInfo> known_study_integrators();

// Every integrator a study can name (integrators/catalog.hpp), each family's own schemes included.
const IntegratorCatalog& study_catalog();

// The traits of the entry of study_catalog() that `spec` names (a pattern entry's prefix for
// exec:COMMAND and tableau:FILE); nullopt, or InputError naming the integrator, for none.
std::optional<IntegratorTraits> find_integrator_traits(const std::string& spec);
IntegratorTraits integrator_traits(const std::string& spec);
// The integrator of that name for a study of `case_name`; throws InputError naming the integrator
// for an unknown one, or a problem's own integrator given with another problem's case. `exec`
// configures an exec:COMMAND integrator (its command is the name's rest).
std::unique_ptr<Integrator> make_study_integrator(const std::string& name, const CvodeSettings& cvode,
                                                  const std::string& case_name,
                                                  const exchange::ExecSettings& exec = {});

}  // namespace dlpverify::families
