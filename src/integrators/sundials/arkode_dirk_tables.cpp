#include "integrators/sundials/arkode_dirk_tables.hpp"

#include <arkode/arkode_butcher_dirk.h>

#include <iterator>

#include "dlpverify/errors.hpp"

namespace dlpverify {

namespace {

struct NamedDirkTable {
  const char* name;
  ARKODE_DIRKTableID id;
};

// Every DIRK table of arkode_butcher_dirk.h (SUNDIALS 6.4.1). Names are checked here, before
// SUNDIALS sees them: ARKodeButcherTable_LoadDIRKByName prints to stderr for an unknown name,
// bypassing any error handler.
#define DLPVERIFY_DIRK_TABLE(id) NamedDirkTable{#id, id}
constexpr NamedDirkTable kDirkTables[] = {
    DLPVERIFY_DIRK_TABLE(ARKODE_SDIRK_2_1_2),           DLPVERIFY_DIRK_TABLE(ARKODE_BILLINGTON_3_3_2),
    DLPVERIFY_DIRK_TABLE(ARKODE_TRBDF2_3_3_2),          DLPVERIFY_DIRK_TABLE(ARKODE_KVAERNO_4_2_3),
    DLPVERIFY_DIRK_TABLE(ARKODE_ARK324L2SA_DIRK_4_2_3), DLPVERIFY_DIRK_TABLE(ARKODE_CASH_5_2_4),
    DLPVERIFY_DIRK_TABLE(ARKODE_CASH_5_3_4),            DLPVERIFY_DIRK_TABLE(ARKODE_SDIRK_5_3_4),
    DLPVERIFY_DIRK_TABLE(ARKODE_KVAERNO_5_3_4),         DLPVERIFY_DIRK_TABLE(ARKODE_ARK436L2SA_DIRK_6_3_4),
    DLPVERIFY_DIRK_TABLE(ARKODE_KVAERNO_7_4_5),         DLPVERIFY_DIRK_TABLE(ARKODE_ARK548L2SA_DIRK_8_4_5),
    DLPVERIFY_DIRK_TABLE(ARKODE_ARK437L2SA_DIRK_7_3_4), DLPVERIFY_DIRK_TABLE(ARKODE_ARK548L2SAb_DIRK_8_4_5),
    DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK324L2SA_4_2_3),   DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK325L2SA_5_2_3),
    DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK32I5L2SA_5_2_3),  DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK436L2SA_6_3_4),
    DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK43I6L2SA_6_3_4),  DLPVERIFY_DIRK_TABLE(ARKODE_QESDIRK436L2SA_6_3_4),
    DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK437L2SA_7_3_4),   DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK547L2SA_7_4_5),
    DLPVERIFY_DIRK_TABLE(ARKODE_ESDIRK547L2SA2_7_4_5),
};
#undef DLPVERIFY_DIRK_TABLE
static_assert(std::size(kDirkTables) == ARKODE_MAX_DIRK_NUM - ARKODE_MIN_DIRK_NUM + 1,
              "this SUNDIALS has DIRK tables the list above does not name");

sun::ButcherTable load(ARKODE_DIRKTableID id) {
  sun::ButcherTable table(ARKodeButcherTable_LoadDIRK(id));
  sun::check_created(table.get(), "ARKodeButcherTable_LoadDIRK");
  return table;
}

}  // namespace

const std::vector<ArkodeTableInfo>& arkode_dirk_tables() {
  static const std::vector<ArkodeTableInfo> tables = [] {
    std::vector<ArkodeTableInfo> list;
    for (const NamedDirkTable& named : kDirkTables) {
      const sun::ButcherTable table = load(named.id);
      list.push_back({named.name, table->stages, table->q, table->p});
    }
    return list;
  }();
  return tables;
}

sun::ButcherTable load_arkode_dirk_table(const std::string& name) {
  for (const NamedDirkTable& named : kDirkTables)
    if (name == named.name) return load(named.id);
  throw InputError("integrator", name, "unknown ARKODE DIRK table");
}

}  // namespace dlpverify
