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

namespace {

template <const auto& Tableau>
std::unique_ptr<Integrator> make_runge_kutta(const std::string& name) {
  return std::make_unique<ExplicitRungeKutta<Tableau>>(name);
}

// The built-in explicit Runge–Kutta methods, one row each: the name a study gives, the order, the
// summary `dlpverify cases` prints, and the tableau it steps (include/dlpverify/runge_kutta.hpp).
struct RungeKuttaMethod {
  const char* name;
  int order;
  const char* summary;
  std::unique_ptr<Integrator> (*make)(const std::string& name);
};

constexpr RungeKuttaMethod kRungeKuttaMethods[] = {
    {"rk2", 2, "explicit midpoint, Kuhl & Grote's scheme (docs/model.md §3)", make_runge_kutta<tableau::midpoint>},
    {"euler", 1, "forward Euler", make_runge_kutta<tableau::euler>},
    {"heun", 2, "Heun / explicit trapezoid", make_runge_kutta<tableau::heun>},
    {"rk4", 4, "classical Runge-Kutta", make_runge_kutta<tableau::rk4>},
};

}  // namespace

std::vector<std::string> runge_kutta_names() {
  std::vector<std::string> names;
  for (const RungeKuttaMethod& method : kRungeKuttaMethods) names.emplace_back(method.name);
  return names;
}

std::vector<IntegratorInfo> known_integrators() {
  std::vector<IntegratorInfo> list;
  for (const RungeKuttaMethod& method : kRungeKuttaMethods)
    list.push_back({method.name, method.order, method.summary, runge_kutta_traits()});
  list.push_back({"cvode", 0, "SUNDIALS CVODE, Adams or BDF, variable order and step (--rtol, --method)",
                  sundials_adaptive_traits(true)});
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
  for (const RungeKuttaMethod& method : kRungeKuttaMethods)
    if (name == method.name) return method.make(name);
  if (name == "cvode" || name.rfind("arkode-erk:", 0) == 0) return make_sundials_integrator(name, settings);
  std::string known;
  for (const RungeKuttaMethod& method : kRungeKuttaMethods) known += std::string(method.name) + ", ";
  throw InputError("integrator", name, "unknown integrator (known: " + known + "cvode, arkode-erk:TABLE; see `dlpverify cases`)");
}

}  // namespace dlpverify
