#include "integrators/registry.hpp"

#include "integrators/sundials/arkode_adaptive.hpp"
#include "integrators/sundials/arkode_erk_integrator.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/errors.hpp"

namespace dlpverify {

IntegratorTraits runge_kutta_traits() {
  IntegratorTraits t;
  t.reach = IntegratorTraits::Reach::each_member;  // include/dlpverify/runge_kutta.hpp: one member per lane
  return t;
}

IntegratorTraits sundials_fixed_traits() {
  IntegratorTraits t;
  t.reach = IntegratorTraits::Reach::across_ranks;
  t.state_vectors = true;
  return t;
}

IntegratorTraits sundials_adaptive_traits(bool cvode) {
  IntegratorTraits t = sundials_fixed_traits();
  t.tolerance_driven = true;
  t.cvode_settings = cvode;
  return t;
}

std::vector<IntegratorInfo> known_integrators() {
  std::vector<IntegratorInfo> list{
      {"rk2", 2, "explicit midpoint, Kuhl & Grote's scheme (docs/model.md §3)", runge_kutta_traits()},
      {"euler", 1, "forward Euler", runge_kutta_traits()},
      {"heun", 2, "Heun / explicit trapezoid", runge_kutta_traits()},
      {"rk4", 4, "classical Runge-Kutta", runge_kutta_traits()},
      {"cvode", 0, "SUNDIALS CVODE, Adams or BDF, variable order and step (--rtol, --method)", sundials_adaptive_traits(true)},
  };
  for (const ArkodeTableInfo& table : arkode_erk_tables())
    list.push_back({"arkode-erk:" + table.name, table.order,
                    "SUNDIALS ARKODE explicit table, " + std::to_string(table.stages) + " stages, fixed step",
                    sundials_fixed_traits()});
  return list;
}

std::vector<IntegratorInfo> adaptive_integrators() {
  std::vector<IntegratorInfo> list{
      {"cvode", 0, "SUNDIALS CVODE, Adams or BDF (--method), atol scaled with rtol", sundials_adaptive_traits(true)}};
  for (const ArkodeAdaptiveTable& table : arkode_adaptive_tables()) {
    const ArkodeTableInfo& info = table.info;
    list.push_back({"arkode-adaptive:" + info.name, info.order,
                    std::string(table.implicit ? "ARKODE implicit (DIRK) table, Newton + matrix-free GMRES, "
                                               : "ARKODE explicit table, ") +
                        std::to_string(info.stages) + " stages, embedding of order " + std::to_string(info.embedding_order),
                    sundials_adaptive_traits(false)});
  }
  return list;
}

std::unique_ptr<Integrator> make_integrator(const std::string& name, const CvodeSettings& settings) {
  if (name == "rk2") return std::make_unique<ExplicitRungeKutta<tableau::midpoint>>(name);
  if (name == "euler") return std::make_unique<ExplicitRungeKutta<tableau::euler>>(name);
  if (name == "heun") return std::make_unique<ExplicitRungeKutta<tableau::heun>>(name);
  if (name == "rk4") return std::make_unique<ExplicitRungeKutta<tableau::rk4>>(name);
  if (name == "cvode" || name.rfind("arkode-erk:", 0) == 0) return make_sundials_integrator(name, settings);
  throw InputError("integrator", name, "unknown integrator (known: rk2, euler, heun, rk4, cvode, arkode-erk:TABLE; see `dlpverify cases`)");
}

}  // namespace dlpverify
