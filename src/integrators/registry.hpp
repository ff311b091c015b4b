// The integrators a study can name, and how to make one.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/sundials/cvode_integrator.hpp"
#include "dlpverify/integrator.hpp"

namespace dlpverify {

struct IntegratorInfo {
  std::string name;
  int order;  // 0: variable order
  std::string summary;
};

// rk2, euler, heun, rk4, cvode, and arkode-erk:TABLE for every ARKODE explicit table.
std::vector<IntegratorInfo> known_integrators();

// The integrators a study by --tolerances sweeps, which are not levels' integrators: cvode, and
// arkode-adaptive:TABLE for every ARKODE table with an embedding, explicit (ERK) and implicit
// (DIRK), at the table's order.
std::vector<IntegratorInfo> adaptive_integrators();

// Makes an integrator by name (`settings` apply to cvode). Throws InputError naming the
// integrator for an unknown one.
std::unique_ptr<Integrator> make_integrator(const std::string& name, const CvodeSettings& settings = {});

}  // namespace dlpverify
