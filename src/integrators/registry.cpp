#include "integrators/registry.hpp"

#include "integrators/runge_kutta.hpp"
#include "io/errors.hpp"

namespace dlpverify {

const std::vector<IntegratorInfo>& fixed_step_integrators() {
  static const std::vector<IntegratorInfo> list{
      {"rk2", 2, "explicit midpoint, the seed's scheme (SPEC §3)"},
      {"euler", 1, "forward Euler"},
      {"heun", 2, "Heun / explicit trapezoid"},
      {"rk4", 4, "classical Runge-Kutta"},
  };
  return list;
}

std::unique_ptr<Integrator> make_fixed_step_integrator(const std::string& name) {
  if (name == "rk2") return std::make_unique<ExplicitRungeKutta<tableau::midpoint>>(name);
  if (name == "euler") return std::make_unique<ExplicitRungeKutta<tableau::euler>>(name);
  if (name == "heun") return std::make_unique<ExplicitRungeKutta<tableau::heun>>(name);
  if (name == "rk4") return std::make_unique<ExplicitRungeKutta<tableau::rk4>>(name);
  std::string known;
  for (const auto& info : fixed_step_integrators()) known += (known.empty() ? "" : ", ") + info.name;
  throw InputError("--integrator", name, "unknown integrator (known: " + known + ")");
}

}  // namespace dlpverify
