#include "cli/problems.hpp"

#include <cmath>

#include "dlpverify/errors.hpp"
#include "exchange/exchange_file.hpp"
#include "io/format.hpp"
#include "problems/dlp/audit_samples.hpp"
#include "problems/dlp/exact/burn.hpp"
#include "problems/dlp/problem.hpp"
#include "problems/gas/cases.hpp"
#include "problems/gas/mpm_update.hpp"
#include "problems/gas/problem.hpp"

namespace dlpverify::cli {

namespace {

Lattice lattice_of(const ProblemOptions& o, const Case& test_case) {
  Lattice lattice;
  lattice.shape = o.shape == "sphere" ? Shape::sphere : Shape::shell;
  lattice.outer = o.outer;
  lattice.inner = o.inner ? *o.inner : Lattice::default_inner(lattice.shape, o.outer);
  lattice.spacing = o.spacing ? *o.spacing : o.parameters.diameter;
  lattice.z_axis_only = test_case.z_axis_only;
  return lattice;
}

BaselineAudit audit_entry(const std::string& name, bool published, const std::string& source, const Problem& sample,
                          double t_end) {
  BaselineAudit audit = audit_closed_form(sample, t_end);
  audit.baseline = name;
  audit.published = published;
  audit.source = source;
  return audit;
}

// ---- the gas cases ------------------------------------------------------------------------------

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

// Which options belong to which problem, as (option, set away from its default).
std::vector<std::pair<const char*, bool>> dlp_options_set(const ProblemOptions& o) {
  const ProblemOptions d;
  const Parameters& p = o.parameters;
  const Parameters& q = d.parameters;
  return {{"--shape", o.shape != d.shape}, {"--outer", o.outer != d.outer}, {"--inner", o.inner.has_value()},
          {"--spacing", o.spacing.has_value()}, {"--us", o.expansion_speed != d.expansion_speed},
          {"--diameter", p.diameter != q.diameter}, {"--rho-p", p.rho_particle != q.rho_particle},
          {"--cs", p.cs_particle != q.cs_particle}, {"--t-particle", p.t_particle != q.t_particle},
          {"--rho-gas", p.rho_gas != q.rho_gas}, {"--mu-gas", p.mu_gas != q.mu_gas}, {"--cp-gas", p.cp_gas != q.cp_gas},
          {"--prandtl", p.prandtl != q.prandtl}, {"--t-gas", p.t_gas != q.t_gas}, {"--cd", p.cd != q.cd},
          {"--g", p.gravity != q.gravity}, {"--cb", p.burn_rate != q.burn_rate}};
}

std::vector<std::pair<const char*, bool>> gas_options_set(const GasOptions& g) {
  const GasOptions d;
  return {{"--parcels", g.parcels != d.parcels}, {"--period", g.period != d.period},
          {"--j-min-low", g.j_min_low != d.j_min_low}, {"--j-min-high", g.j_min_high != d.j_min_high},
          {"--t-spread", g.t_spread != d.t_spread}, {"--p-ref", g.p_ref.has_value()}, {"--t-ref", g.t_ref.has_value()},
          {"--molar-mass", g.molar_mass.has_value()}, {"--rho0", g.rho0.has_value()}, {"--gamma", g.gamma.has_value()},
          {"--vdw-a", g.vdw_a.has_value()}, {"--vdw-b", g.vdw_b.has_value()}};
}

}  // namespace

std::vector<CaseEntry> all_cases() {
  std::vector<CaseEntry> entries;
  for (const Case& c : dlpverify::all_cases())
    entries.push_back({c.name, "dlp", c.summary, describe_terms(c.terms), c.reference_detail, c.solution != nullptr,
                       {c.defaults.t_end, c.defaults.dt, c.defaults.levels}});
  for (const gas::GasCase& c : gas::all_gas_cases())
    entries.push_back({c.name, "gas", c.summary, c.gas, make_gas_problem({}, c)->reference_detail(), true, c.defaults});
  return entries;
}

const CaseEntry& find_case_entry(const std::string& name) {
  static const std::vector<CaseEntry> entries = all_cases();
  std::string names;
  for (const CaseEntry& c : entries) {
    if (c.name == name) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throw InputError("--case", name, "unknown case (known: " + names + ")");
}

std::string problem_of_case(const std::string& case_name) { return find_case_entry(case_name).problem; }

void check_problem_options(const ProblemOptions& o) {
  const std::string problem = problem_of_case(o.case_name);
  const auto foreign = problem == "gas" ? dlp_options_set(o) : gas_options_set(o.gas);
  for (const auto& [option, set] : foreign)
    if (set)
      throw InputError(std::string(option) + ": applies to the " + (problem == "gas" ? "DLP cloud's" : "gas adiabat") +
                       " cases, not --case " + o.case_name);
}

void fill_case_defaults(ProblemOptions& o) {
  if (problem_of_case(o.case_name) == "gas") {
    const gas::GasCase& c = *gas::find_gas_case(o.case_name);
    GasOptions& g = o.gas;
    if (!g.p_ref) g.p_ref = c.spec.P0;
    if (!g.t_ref) g.t_ref = c.spec.T0;
    if (!g.molar_mass && !g.rho0) g.molar_mass = c.spec.molar_mass;
    if (!g.gamma) g.gamma = value_text(c.spec.gamma);
    if (!g.vdw_a) g.vdw_a = c.spec.a;
    if (!g.vdw_b) g.vdw_b = c.spec.b;
    return;
  }
  if (!o.inner) o.inner = Lattice::default_inner(o.shape == "sphere" ? Shape::sphere : Shape::shell, o.outer);
  if (!o.spacing) o.spacing = o.parameters.diameter;
}

std::vector<IntegratorInfo> known_study_integrators() {
  std::vector<IntegratorInfo> list = known_integrators();
  for (const gas::UpdateInfo& u : gas::temperature_updates()) list.push_back({u.name, u.order, u.summary});
  list.push_back({"exec:COMMAND", 0, "your own program, run per level on an HDF5 file (docs/exchange.md); --exec-order P"});
  return list;
}

std::unique_ptr<Integrator> make_study_integrator(const std::string& name, const CvodeSettings& cvode,
                                                  const std::string& case_name, const exchange::ExecSettings& exec) {
  if (name.rfind(exchange::kExecPrefix, 0) == 0) {
    exchange::ExecSettings settings = exec;
    settings.command = name.substr(std::string(exchange::kExecPrefix).size());
    try {
      return std::make_unique<exchange::ExecIntegrator>(settings);
    } catch (const exchange::ExchangeError& e) {
      throw InputError("--integrator", name, e.what());
    }
  }
  if (std::unique_ptr<Integrator> update = gas::make_temperature_update(name)) {
    if (problem_of_case(case_name) != "gas")
      throw InputError("--integrator", name, "updates gas parcels along their paths; use it with --case adiabat-ideal or adiabat-vdw");
    return update;
  }
  return make_integrator(name, cvode);
}

ProblemSize problem_size(const ProblemOptions& o) {
  if (gas::find_gas_case(o.case_name)) return {o.gas.parcels, 2, "--parcels", std::to_string(o.gas.parcels)};
  return {count_lattice_points(lattice_of(o, find_case(o.case_name))), kFields, "--outer", std::to_string(o.outer)};
}

std::unique_ptr<Problem> make_problem(const ProblemOptions& o) {
  if (const gas::GasCase* c = gas::find_gas_case(o.case_name)) return make_gas_problem(o.gas, *c);
  const Case& test_case = find_case(o.case_name);
  return std::make_unique<DlpProblem>(test_case, o.parameters, lattice_of(o, test_case), Launch{o.expansion_speed});
}

Eigen::ArrayXd member_coordinate(const Problem& problem) {
  return dynamic_cast<const DlpProblem&>(problem).similarity_coordinate();
}

void check_duration(const ProblemOptions& o, double t_end) {
  if (const gas::GasCase* c = gas::find_gas_case(o.case_name)) return make_gas_problem(o.gas, *c)->check_paths(t_end);
  if (find_case(o.case_name).terms.burning) exact::check_before_burn_out(o.parameters, t_end);
}

BaselineAudit audit_case(const ProblemOptions& o, const std::string& case_name, double t_end) {
  if (const gas::GasCase* c = gas::find_gas_case(case_name)) {
    const auto sample = make_gas_problem(o.gas, *c);
    return audit_entry(c->name, false, sample->reference_detail(), *sample, t_end);
  }
  const Case& test_case = find_case(case_name);
  return audit_entry(test_case.name, false, test_case.reference_detail, *audit_sample(test_case, o.parameters), t_end);
}

std::vector<BaselineAudit> audit_all() {
  std::vector<BaselineAudit> audits;
  const Parameters defaults;
  for (const Case& c : dlpverify::all_cases())
    if (c.solution != nullptr)
      audits.push_back(audit_entry(c.name, false, c.reference_detail, *audit_sample(c, defaults), c.defaults.t_end));
  for (const gas::GasCase& c : gas::all_gas_cases()) {
    const auto sample = make_gas_problem({}, c);
    audits.push_back(audit_entry(c.name, false, sample->reference_detail(), *sample, c.defaults.t_end));
  }
  for (const PublishedFormula& formula : published_formulas(defaults))
    audits.push_back(audit_entry(formula.name, true, formula.source, *formula.sample, 0.01));
  return audits;
}

}  // namespace dlpverify::cli
