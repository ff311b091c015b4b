// The thermal cases (docs/model.md §7.3): particle cooling by convection and radiation, and the
// seed's coupled systems for staggering.
#include "dlpverify/closed_form.hpp"
#include "families/family.hpp"
#include "io/value_checks.hpp"
#include "harness/distribution.hpp"
#include "problems/thermal/cases.hpp"
#include "problems/thermal/cooling.hpp"
#include "problems/thermal/coupled.hpp"

namespace dlpverify::families {

namespace {

thermal::CoolingPhysics cooling_physics(const ThermalOptions& t, const thermal::ThermalCase& c) {
  thermal::CoolingPhysics p = c.physics;
  if (t.h_c) p.h_c = *t.h_c;
  if (t.theta_gas) p.theta_gas = *t.theta_gas;
  if (t.theta_surroundings) p.theta_surroundings = *t.theta_surroundings;
  p.density = t.particle_density;
  p.heat_capacity = t.heat_capacity;
  return p;
}

std::unique_ptr<Problem> make_thermal(const ThermalOptions& t, const thermal::ThermalCase& c) {
  if (c.equations > 0)
    return std::make_unique<thermal::CoupledSystem>(c.name, c.equations, thermal::CouplingConstants{t.a, t.b, t.c}, t.systems);
  const thermal::CoolingPopulation population{t.particles, t.d_min, t.d_max, t.emissivity_min, t.emissivity_max,
                                              t.theta0_min, t.theta0_max};
  // Each rank keeps the rates of its own particles alone (docs/mpi.md).
  return std::make_unique<thermal::CoolingProblem>(c.name, cooling_physics(t, c), population, own_members(t.particles));
}

void require_order(const char* low_option, double low, const char* high_option, double high) {
  if (low > high)
    throw InputError(low_option, value_text(low), std::string("is larger than ") + high_option + " = " + value_text(high));
}

const std::string kCooling = "Cooling particles (cooling cases, docs/model.md §7.3)";
const std::string kCoupled = "Coupled systems (stagger cases, docs/model.md §7.3)";

class ThermalFamily final : public Family {
 public:
  std::string name() const override { return "thermal"; }
  std::string title() const override { return "the thermal cases (cooling, stagger)"; }

  std::vector<CaseEntry> cases() const override {
    std::vector<CaseEntry> entries;
    for (const thermal::ThermalCase& c : thermal::all_thermal_cases()) {
      const auto sample = make_thermal({}, c);
      entries.push_back({c.name, "thermal", c.summary, c.terms, reference_detail(*sample), has_closed_form(*sample),
                         c.defaults});
    }
    return entries;
  }

  std::vector<FamilyOption> options(ProblemOptions& p) const override {
    ThermalOptions& o = p.thermal;
    return {{"--particles", "Number of particles", kCooling, &o.particles},
            {"--h-c", "Convection coefficient h_c [W/(m² K)] [default: the case's]", kCooling, &o.h_c},
            {"--theta-gas", "Gas temperature θ_o [K] [default: the case's]", kCooling, &o.theta_gas},
            {"--theta-surroundings", "Surroundings' temperature θ_s [K] [default: the case's]", kCooling,
             &o.theta_surroundings},
            {"--particle-density", "Particle density ρ [kg/m³]", kCooling, &o.particle_density},
            {"--heat-capacity", "Particle heat capacity C [J/(kg K)]", kCooling, &o.heat_capacity},
            {"--d-min", "Smallest particle diameter [m]", kCooling, &o.d_min},
            {"--d-max", "Largest particle diameter [m]", kCooling, &o.d_max},
            {"--emissivity-min", "Lowest emissivity ε", kCooling, &o.emissivity_min},
            {"--emissivity-max", "Highest emissivity ε", kCooling, &o.emissivity_max},
            {"--theta0-min", "Lowest initial temperature [K]", kCooling, &o.theta0_min},
            {"--theta0-max", "Highest initial temperature [K]", kCooling, &o.theta0_max},
            {"--a", "Constant a of a w1' + w2 = 0", kCoupled, &o.a},
            {"--b", "Constant b of b w2' + w1 = 0 (2x2) or b w2' + w3 = 0 (3x3)", kCoupled, &o.b},
            {"--c", "Constant c of c w3'' + w1 = 0 (3x3)", kCoupled, &o.c},
            {"--systems", "Number of initial conditions integrated together", kCoupled, &o.systems}};
  }

  void validate(const ProblemOptions& p) const override {
    const ThermalOptions& o = p.thermal;
    if (o.particles < 1 || o.particles > 10000000) throw InputError("--particles", std::to_string(o.particles), "must lie in [1, 1e7]");
    if (o.systems < 1 || o.systems > 1000000) throw InputError("--systems", std::to_string(o.systems), "must lie in [1, 1e6]");
    if (o.h_c) require_non_negative("--h-c", *o.h_c);
    if (o.theta_gas) require_non_negative("--theta-gas", *o.theta_gas);
    if (o.theta_surroundings) require_non_negative("--theta-surroundings", *o.theta_surroundings);
    require_positive("--particle-density", o.particle_density);
    require_positive("--heat-capacity", o.heat_capacity);
    require_positive("--d-min", o.d_min);
    require_positive("--d-max", o.d_max);
    require_order("--d-min", o.d_min, "--d-max", o.d_max);
    require_positive("--emissivity-min", o.emissivity_min);
    if (!(o.emissivity_max <= 1.0)) throw InputError("--emissivity-max", value_text(o.emissivity_max), "must lie in (0, 1]");
    require_order("--emissivity-min", o.emissivity_min, "--emissivity-max", o.emissivity_max);
    require_positive("--theta0-min", o.theta0_min);
    require_positive("--theta0-max", o.theta0_max);
    require_order("--theta0-min", o.theta0_min, "--theta0-max", o.theta0_max);
    require_positive("--a", o.a);
    require_positive("--b", o.b);
    require_positive("--c", o.c);
  }

  // A coupled system's constants, or the cooling population's options: the case's group alone.
  nlohmann::json options_json(const ProblemOptions& p) const override {
    ProblemOptions values = p;
    const std::string& group = thermal::find_thermal_case(p.case_name)->equations > 0 ? kCoupled : kCooling;
    std::vector<FamilyOption> own;
    for (FamilyOption& option : options(values))
      if (option.group == group) own.push_back(std::move(option));
    return families::options_json(own);
  }

  void fill_defaults(ProblemOptions& p) const override {
    const thermal::ThermalCase& c = *thermal::find_thermal_case(p.case_name);
    if (c.equations > 0) return;
    ThermalOptions& o = p.thermal;
    if (!o.h_c) o.h_c = c.physics.h_c;
    if (!o.theta_gas) o.theta_gas = c.physics.theta_gas;
    if (!o.theta_surroundings) o.theta_surroundings = c.physics.theta_surroundings;
  }

  bool closed_form(const ProblemOptions& p) const override { return has_closed_form(*make(p)); }

  ProblemSize size(const ProblemOptions& p) const override {
    const thermal::ThermalCase& c = *thermal::find_thermal_case(p.case_name);
    if (c.equations > 0) return {p.thermal.systems, c.equations == 2 ? 2 : 4, "--systems", std::to_string(p.thermal.systems)};
    return {p.thermal.particles, 1, "--particles", std::to_string(p.thermal.particles)};
  }

  std::unique_ptr<Problem> make(const ProblemOptions& p) const override {
    return make_thermal(p.thermal, *thermal::find_thermal_case(p.case_name));
  }

  BaselineAudit audit(const ProblemOptions& p, const std::string& case_name, double t_end) const override {
    const auto sample = make_thermal(p.thermal, *thermal::find_thermal_case(case_name));
    return named_audit(case_name, false, reference_detail(*sample), *sample, t_end);
  }

  std::vector<BaselineAudit> default_audits() const override {
    std::vector<BaselineAudit> audits;
    for (const thermal::ThermalCase& c : thermal::all_thermal_cases()) {
      const auto sample = make_thermal({}, c);
      if (has_closed_form(*sample))
        audits.push_back(named_audit(c.name, false, reference_detail(*sample), *sample, c.defaults.t_end));
    }
    return audits;
  }
};

}  // namespace

const Family& thermal_family() {
  static const ThermalFamily family;
  return family;
}

}  // namespace dlpverify::families
