// The gas adiabats' cases (docs/model.md §7.1): gas parcels on prescribed compression paths, with
// the gas's own temperature updates (NairnMPM's) as integrators.
#include "dlpverify/closed_form.hpp"
#include "families/family.hpp"
#include "io/value_checks.hpp"
#include "problems/gas/cases.hpp"
#include "problems/gas/mpm_update.hpp"
#include "problems/gas/problem.hpp"

namespace dlpverify::families {

namespace {

double gamma_of(const std::string& text) {
  if (text == "monatomic") return gas::kGammaMonatomic;
  if (text == "diatomic") return gas::kGammaDiatomic;
  std::size_t used = 0;
  double gamma = std::nan("");
  try {
    gamma = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(gamma) || gamma <= 1.0)
    throw InputError("--gamma", text, "must be monatomic, diatomic or a number greater than 1");
  return gamma;
}

// The gas of a case with the options' overrides. --rho0 stands for the molar mass: ρ0 = M_g/v0.
gas::Material material_of(const GasOptions& g, const gas::GasCase& c) {
  gas::MolarSpec spec = c.spec;
  if (c.spec.a == 0.0 && c.spec.b == 0.0) {  // the ideal-gas case takes no van der Waals constants
    if (g.vdw_a && *g.vdw_a != 0.0) throw InputError("--vdw-a", value_text(*g.vdw_a), c.name + " is the ideal gas; use adiabat-vdw");
    if (g.vdw_b && *g.vdw_b != 0.0) throw InputError("--vdw-b", value_text(*g.vdw_b), c.name + " is the ideal gas; use adiabat-vdw");
  }
  if (g.p_ref) spec.P0 = *g.p_ref;
  if (g.t_ref) spec.T0 = *g.t_ref;
  if (g.gamma) spec.gamma = gamma_of(*g.gamma);
  if (g.vdw_a) spec.a = *g.vdw_a;
  if (g.vdw_b) spec.b = *g.vdw_b;
  if (g.molar_mass) spec.molar_mass = *g.molar_mass;
  if (g.rho0) spec.molar_mass = gas::molar_mass_for_density(spec, *g.rho0);
  return gas::Material::from_molar(spec);
}

gas::Population population_of(const GasOptions& g) {
  return {.parcels = g.parcels, .j_min_low = g.j_min_low, .j_min_high = g.j_min_high, .period = g.period,
          .temperature_spread = g.t_spread};
}

std::unique_ptr<gas::GasProblem> make_gas_problem(const GasOptions& g, const gas::GasCase& c) {
  return std::make_unique<gas::GasProblem>(c.name, material_of(g, c), population_of(g));
}

class GasFamily final : public Family {
 public:
  std::string name() const override { return "gas"; }
  std::string title() const override { return "the gas adiabat cases"; }

  std::vector<CaseEntry> cases() const override {
    std::vector<CaseEntry> entries;
    for (const gas::GasCase& c : gas::all_gas_cases())
      entries.push_back({c.name, "gas", c.summary, c.gas, reference_detail(*make_gas_problem({}, c)), true, c.defaults});
    return entries;
  }

  // The parcels and their paths, then the gas (unset: the case's gas).
  std::vector<FamilyOption> options(ProblemOptions& p) const override {
    GasOptions& o = p.gas;
    const std::string group = "Gas parcels (adiabat cases, docs/model.md §7.1)";
    return {{"--parcels", "Number of gas parcels", group, &o.parcels},
            {"--period", "Period P of every parcel's compression path J(t) [s]", group, &o.period},
            {"--j-min-low", "Deepest compression J_min of the first parcel", group, &o.j_min_low},
            {"--j-min-high", "Deepest compression J_min of the last parcel", group, &o.j_min_high},
            {"--t-spread", "Initial temperatures spread over T0 (1 ± spread)", group, &o.t_spread},
            {"--p-ref", "Reference pressure P0 [Pa] [default: the case's gas]", group, &o.p_ref},
            {"--t-ref", "Reference temperature T0 [K] [default: the case's gas]", group, &o.t_ref},
            {"--molar-mass", "Molar mass M_g [kg/mol] [default: the case's gas]", group, &o.molar_mass},
            {"--rho0", "Reference density ρ0 [kg/m³], instead of --molar-mass", group, &o.rho0},
            {"--gamma", "Ratio of specific heats: monatomic | diatomic | a number > 1 [default: the case's gas]", group,
             &o.gamma},
            {"--vdw-a", "van der Waals a [Pa m⁶/mol²] (adiabat-vdw) [default: the case's gas]", group, &o.vdw_a},
            {"--vdw-b", "van der Waals b [m³/mol] (adiabat-vdw) [default: the case's gas]", group, &o.vdw_b}};
  }

  void validate(const ProblemOptions& o) const override {
    const GasOptions& g = o.gas;
    if (g.parcels < 1 || g.parcels > 10000000) throw InputError("--parcels", std::to_string(g.parcels), "must lie in [1, 1e7]");
    if (g.molar_mass && g.rho0) throw InputError("--rho0", value_text(*g.rho0), "and --molar-mass both given; give one of them");
  }

  void fill_defaults(ProblemOptions& o) const override {
    const gas::GasCase& c = *gas::find_gas_case(o.case_name);
    GasOptions& g = o.gas;
    if (!g.p_ref) g.p_ref = c.spec.P0;
    if (!g.t_ref) g.t_ref = c.spec.T0;
    if (!g.molar_mass && !g.rho0) g.molar_mass = c.spec.molar_mass;
    if (!g.gamma) g.gamma = value_text(c.spec.gamma);
    if (!g.vdw_a) g.vdw_a = c.spec.a;
    if (!g.vdw_b) g.vdw_b = c.spec.b;
  }

  // The state is T; its measured copy has P beside it.
  ProblemSize size(const ProblemOptions& o) const override {
    return {o.gas.parcels, 2, "--parcels", std::to_string(o.gas.parcels)};
  }

  std::unique_ptr<Problem> make(const ProblemOptions& o) const override {
    return make_gas_problem(o.gas, *gas::find_gas_case(o.case_name));
  }

  void check_duration(const ProblemOptions& o, double t_end) const override {
    make_gas_problem(o.gas, *gas::find_gas_case(o.case_name))->check_paths(t_end);
  }

  BaselineAudit audit(const ProblemOptions& o, const std::string& case_name, double t_end) const override {
    const auto sample = make_gas_problem(o.gas, *gas::find_gas_case(case_name));
    return named_audit(case_name, false, reference_detail(*sample), *sample, t_end);
  }

  std::vector<BaselineAudit> default_audits() const override {
    std::vector<BaselineAudit> audits;
    for (const gas::GasCase& c : gas::all_gas_cases()) {
      const auto sample = make_gas_problem({}, c);
      audits.push_back(named_audit(c.name, false, reference_detail(*sample), *sample, c.defaults.t_end));
    }
    return audits;
  }

  std::vector<IntegratorInfo> integrators() const override {
    std::vector<IntegratorInfo> list;
    IntegratorTraits own;  // a scheme of the gas model's own equations, not of Problem::rhs
    own.calls_problem_rhs = false;
    for (const gas::UpdateInfo& u : gas::temperature_updates()) list.push_back({u.name, u.order, u.summary, own});
    return list;
  }

  std::unique_ptr<Integrator> make_integrator(const std::string& name) const override {
    return gas::make_temperature_update(name);
  }
};

}  // namespace

const Family& gas_family() {
  static const GasFamily family;
  return family;
}

}  // namespace dlpverify::families
