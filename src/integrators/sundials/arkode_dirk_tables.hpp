// ARKODE's diagonally implicit Runge–Kutta tables (arkode_butcher_dirk.h: SDIRK, ESDIRK and the
// implicit halves of the additive pairs), by their ARKODE names, for `arkode-adaptive:TABLE`.
#pragma once

#include <string>
#include <vector>

#include "integrators/sundials/arkode_erk_integrator.hpp"  // ArkodeTableInfo
#include "sundials/sundials_support.hpp"

namespace dlpverify {

// The DIRK tables of this SUNDIALS (6.4.1: 23 tables, ARKODE_SDIRK_2_1_2 … ARKODE_ESDIRK547L2SA2_7_4_5).
const std::vector<ArkodeTableInfo>& arkode_dirk_tables();

// The table of that name, loaded. Throws InputError for a name not in arkode_dirk_tables().
sun::ButcherTable load_arkode_dirk_table(const std::string& name);

}  // namespace dlpverify
