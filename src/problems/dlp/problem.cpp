#include "problems/dlp/problem.hpp"

#include <cmath>
#include <limits>

#include "problems/dlp/exact/time_scale.hpp"
#include "problems/dlp/exact/burn.hpp"
#include "problems/dlp/exact/cloud_solution.hpp"
#include "problems/dlp/exact/vertical_drag_gravity.hpp"

namespace dlpverify::dlp {

DlpProblem::DlpProblem(const Case& test_case, const Parameters& parameters, const Lattice& lattice,
                       const Launch& launch)
    : DlpProblem(test_case, parameters, Cloud(), dlp::initial_time(lattice, launch)) {
  launch_ = launch;
  lattice_ = lattice;
  members_ = static_cast<Eigen::Index>(count_lattice_points(lattice));
}

DlpProblem::DlpProblem(const Case& test_case, const Parameters& parameters, Cloud initial, double t0,
                       exact::ParticleSolution other_solution, std::string solution_detail)
    : case_(&test_case),
      physics_{parameters, test_case.terms},
      rates_(physics_),
      block_rates_(physics_),
      initial_(std::move(initial)),
      members_(initial_.size()),
      t0_(t0),
      solution_(other_solution ? other_solution : test_case.solution),
      solution_detail_(other_solution ? std::move(solution_detail) : test_case.reference_detail) {
  launch_.expansion_speed = 0.0;  // unknown for a cloud given as it is (set by the lattice constructor)
  provide_capabilities();
}

void DlpProblem::provide_capabilities() {
  if (solution_) provide<ClosedForm>(*this);
  provide<SolutionKinks>(*this);
  provide<TimeScale>(*this);
  provide<InertFields>(*this);
  provide<FusedStepper>(*this);
  provide<CaseReport>(*this);
  provide<MemberNoun>(*this);
  provide<ExchangeDescription>(*this);
  provide<InitialMembers>(*this);
  provide<MemberCoordinate>(*this);
  provide<ExtendedRhs>(*this);
}

State DlpProblem::initial_state() const {
  if (!lattice_) return initial_.state();
  Cloud cloud = make_cloud(*lattice_, launch_, physics_.parameters);
  return std::move(cloud.state());
}

State DlpProblem::initial_members(Eigen::Index first, Eigen::Index count) const {
  if (!lattice_) return initial_.state().middleRows(first, count);
  Cloud cloud = make_cloud_members(*lattice_, launch_, physics_.parameters, first, count);
  return std::move(cloud.state());
}

std::vector<Field> DlpProblem::fields() const {
  return {{"x", "m"}, {"y", "m"}, {"z", "m"}, {"vx", "m/s"}, {"vy", "m/s"}, {"vz", "m/s"}, {"T", "K"}, {"m", "kg"}};
}

std::vector<Variable> DlpProblem::variables() const {
  std::vector<Variable> variables{{"position", X, 3, "m"}, {"velocity", VX, 3, "m/s"}};
  if (physics_.terms.heat) variables.push_back({"temperature", TEMPERATURE, 1, "K"});
  if (physics_.terms.burning) variables.push_back({"mass", MASS, 1, "kg"});
  return variables;
}

// Each particle's solution depends on its own state alone, so `first` changes nothing.
State DlpProblem::solution(Eigen::Index /*first*/, const State& initial, double tau) const {
  // Past burn-out the mass equation has no meaning (and exact::burn would throw inside the
  // OpenMP loop of exact::evaluate): refuse it here, as input.
  if (physics_.terms.burning) exact::check_before_burn_out(physics_.parameters, tau);
  Cloud at_tau = exact::evaluate(solution_, physics_, initial, tau);
  return std::move(at_tau.state());
}

std::vector<double> DlpProblem::kink_times(Eigen::Index /*first*/, const State& initial) const {
  std::vector<double> kinks(static_cast<std::size_t>(initial.rows()), std::numeric_limits<double>::quiet_NaN());
  // −K ‖v‖ v is only once differentiable where v = 0: at the apex of a vertical rise (§4.4).
  if (!(physics_.terms.drag && physics_.terms.gravity)) return kinks;
  const Cloud cloud(initial);
  for (Eigen::Index p = 0; p < initial.rows(); ++p) {
    const ParticleState y0 = cloud.particle(p);
    if (!exact::vertical_motion(y0)) continue;
    const double apex = exact::apex_time(physics_, y0);
    if (apex > 0.0) kinks[static_cast<std::size_t>(p)] = apex;
  }
  return kinks;
}

double DlpProblem::time_scale(Eigen::Index /*member*/, const double* y, double tau) const {
  ParticleState particle;
  for (int f = 0; f < kFields; ++f) particle[f] = y[f];
  return exact::particle_time_scale(physics_, particle, tau);
}

nlohmann::json DlpProblem::parameters() const {
  const Parameters& p = physics_.parameters;
  return {{"diameter", p.diameter},   {"rho_particle", p.rho_particle}, {"cs_particle", p.cs_particle},
          {"t_particle", p.t_particle}, {"rho_gas", p.rho_gas},        {"mu_gas", p.mu_gas},
          {"cp_gas", p.cp_gas},         {"prandtl", p.prandtl},        {"t_gas", p.t_gas},
          {"cd", p.cd},                 {"gravity", p.gravity},        {"burn_rate", p.burn_rate},
          {"terms", describe_terms(physics_.terms)}};
}

// docs/model.md §1 and §8, for a program that implements the right-hand side itself: g points to −z.
ProblemDescription DlpProblem::description() const {
  const Parameters& p = physics_.parameters;
  const Terms& t = physics_.terms;
  auto on = [](bool term) { return std::string(term ? "on" : "off"); };
  return {"dlp",
          {{"diameter", p.diameter, "m"}, {"rho_particle", p.rho_particle, "kg/m^3"},
           {"cs_particle", p.cs_particle, "J/(kg K)"}, {"t_particle", p.t_particle, "K"},
           {"rho_gas", p.rho_gas, "kg/m^3"}, {"mu_gas", p.mu_gas, "Pa s"}, {"cp_gas", p.cp_gas, "J/(kg K)"},
           {"prandtl", p.prandtl, "1"}, {"t_gas", p.t_gas, "K"}, {"cd", p.cd, "1"}, {"gravity", p.gravity, "m/s^2"},
           {"burn_rate", p.burn_rate, "kg/(m^2 s)"}, {"expansion_speed", launch_.expansion_speed, "m/s"}},
          {{"drag", t.drag ? (t.drag_law == DragLaw::constant ? "constant" : "reynolds") : "off"},
           {"gravity", on(t.gravity)}, {"heat", on(t.heat)}, {"burning", on(t.burning)},
           {"terms", describe_terms(t)}},
          {}};
}

std::vector<MemberReduction> DlpProblem::diagnostic_reductions() const {
  return case_->diagnostics ? case_->diagnostics->reductions : std::vector<MemberReduction>{};
}

// A particle's terms depend on its own state only, not on its index.
Eigen::ArrayXXd DlpProblem::member_terms(Eigen::Index /*first*/, const State& initial, const State& finest,
                                         double t_end) const {
  if (!case_->diagnostics) return Eigen::ArrayXXd(initial.rows(), 0);
  const Cloud launch_cloud(initial), final_cloud(finest);
  return case_->diagnostics->terms({physics_, launch_, launch_cloud, final_cloud, t_end});
}

nlohmann::json DlpProblem::diagnostics(const std::vector<double>& reduced, double t_end) const {
  if (!case_->diagnostics) return nlohmann::json::object();
  return case_->diagnostics->report(physics_, launch_, reduced, t_end);
}

Eigen::ArrayXd DlpProblem::member_coordinate(Eigen::Index first, Eigen::Index count) const {
  // r_s0 = u_s t0; a cloud given without its launch: the outermost particle's distance, of all.
  double launch_radius = launch_.expansion_speed * t0_;
  if (!(launch_.expansion_speed > 0.0)) {
    const Eigen::ArrayXd all = distance_from_centre(initial_state());
    launch_radius = all.size() ? all.maxCoeff() : 1.0;
  }
  return distance_from_centre(initial_members(first, count)) / launch_radius;
}

}  // namespace dlpverify::dlp
