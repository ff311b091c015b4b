// The DLP cloud's cases (docs/model.md §1–§4): the lattice cloud launched with the similarity
// solution, and the physics it runs on.
#include "families/family.hpp"
#include "io/value_checks.hpp"
#include "problems/dlp/audit_samples.hpp"
#include "problems/dlp/exact/burn.hpp"
#include "problems/dlp/problem.hpp"

namespace dlpverify::families {

using namespace dlp;  // the DLP cloud's types

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

class DlpFamily final : public Family {
 public:
  std::string name() const override { return "dlp"; }
  std::string title() const override { return "the DLP cloud's cases"; }

  std::vector<CaseEntry> cases() const override {
    std::vector<CaseEntry> entries;
    for (const Case& c : dlp::all_cases())
      entries.push_back({c.name, "dlp", c.summary, describe_terms(c.terms), c.reference_detail, c.solution != nullptr,
                         {c.defaults.t_end, c.defaults.dt, c.defaults.levels}});
    return entries;
  }

  std::vector<FamilyOption> options(ProblemOptions& o) const override {
    Parameters& p = o.parameters;
    const std::string cloud = "Cloud", physics = "Physics (docs/model.md §8)";
    return {{"--shape", "Cloud shape: sphere | shell", cloud, &o.shape},
            {"--outer", "Outer radius R_out in lattice spacings", cloud, &o.outer},
            {"--inner", "Inner radius in lattice spacings [default: 1 (sphere), outer-5 (shell)]", cloud, &o.inner},
            {"--spacing", "Lattice spacing Δ [m] [default: the particle diameter]", cloud, &o.spacing},
            {"--us", "Expansion speed u_s of the cloud boundary [m/s]", cloud, &o.expansion_speed},
            {"--diameter", "Initial particle diameter d0 [m]", physics, &p.diameter},
            {"--rho-p", "Particle density ρ_p [kg/m³]", physics, &p.rho_particle},
            {"--cs", "Particle specific heat c_s [J/(kg K)]", physics, &p.cs_particle},
            {"--t-particle", "Initial particle temperature T_p0 [K]", physics, &p.t_particle},
            {"--rho-gas", "Gas density ρ_a [kg/m³]", physics, &p.rho_gas},
            {"--mu-gas", "Gas viscosity μ_a [Pa s]", physics, &p.mu_gas},
            {"--cp-gas", "Gas specific heat c_p [J/(kg K)]", physics, &p.cp_gas},
            {"--prandtl", "Prandtl number Pr", physics, &p.prandtl},
            {"--t-gas", "Gas temperature T_a [K]", physics, &p.t_gas},
            {"--cd", "Constant drag coefficient C_D", physics, &p.cd},
            {"--g", "Gravity ‖g‖ [m/s²], pointing to −z when the case has gravity", physics, &p.gravity},
            {"--cb", "Burning constant c_b in ṡ = c_b d² [kg/(m² s)]", physics, &p.burn_rate}};
  }

  void validate(const ProblemOptions& o) const override {
    if (o.shape != "sphere" && o.shape != "shell") throw InputError("--shape", o.shape, "must be sphere or shell");
    if (o.outer < 1) throw InputError("--outer", std::to_string(o.outer), "must be at least 1");
    if (o.outer > 2000) throw InputError("--outer", std::to_string(o.outer), "is larger than 2000 (over 3e10 particles)");
    if (o.inner && *o.inner < 0) throw InputError("--inner", std::to_string(*o.inner), "must be zero or positive");
    if (o.inner && *o.inner > o.outer)
      throw InputError("--inner", std::to_string(*o.inner), "is larger than --outer = " + std::to_string(o.outer));
    if (o.spacing) require_positive("--spacing", *o.spacing);
    require_positive("--us", o.expansion_speed);
    const Parameters& p = o.parameters;
    require_positive("--diameter", p.diameter);
    require_positive("--rho-p", p.rho_particle);
    require_positive("--cs", p.cs_particle);
    require_positive("--t-particle", p.t_particle);
    require_positive("--rho-gas", p.rho_gas);
    require_positive("--mu-gas", p.mu_gas);
    require_positive("--cp-gas", p.cp_gas);
    require_positive("--prandtl", p.prandtl);
    require_positive("--t-gas", p.t_gas);
    require_positive("--cd", p.cd);
    require_non_negative("--g", p.gravity);
    require_non_negative("--cb", p.burn_rate);
  }

  void fill_defaults(ProblemOptions& o) const override {
    if (!o.inner) o.inner = Lattice::default_inner(o.shape == "sphere" ? Shape::sphere : Shape::shell, o.outer);
    if (!o.spacing) o.spacing = o.parameters.diameter;
  }

  ProblemSize size(const ProblemOptions& o) const override {
    return {count_lattice_points(lattice_of(o, find_case(o.case_name))), kFields, "--outer", std::to_string(o.outer)};
  }

  std::unique_ptr<Problem> make(const ProblemOptions& o) const override { return make_dlp_problem(o); }

  void check_duration(const ProblemOptions& o, double t_end) const override {
    if (find_case(o.case_name).terms.burning) exact::check_before_burn_out(o.parameters, t_end);
  }

  BaselineAudit audit(const ProblemOptions& o, const std::string& case_name, double t_end) const override {
    const Case& test_case = find_case(case_name);
    return named_audit(test_case.name, false, test_case.reference_detail, *audit_sample(test_case, o.parameters), t_end);
  }

  // Every closed-form case with default parameters, then the source paper's published formulas.
  std::vector<BaselineAudit> default_audits() const override {
    std::vector<BaselineAudit> audits;
    const Parameters defaults;
    for (const Case& c : dlp::all_cases())
      if (c.solution != nullptr)
        audits.push_back(named_audit(c.name, false, c.reference_detail, *audit_sample(c, defaults), c.defaults.t_end));
    for (const PublishedFormula& formula : published_formulas(defaults))
      audits.push_back(named_audit(formula.name, true, formula.source, *formula.sample, 0.01));
    return audits;
  }
};

}  // namespace

std::unique_ptr<DlpProblem> make_dlp_problem(const ProblemOptions& o) {
  const Case& test_case = find_case(o.case_name);
  return std::make_unique<DlpProblem>(test_case, o.parameters, lattice_of(o, test_case), Launch{o.expansion_speed});
}

const Family& dlp_family() {
  static const DlpFamily family;
  return family;
}

}  // namespace dlpverify::families
