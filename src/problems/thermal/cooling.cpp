#include "problems/thermal/cooling.hpp"

#include <cmath>

#include "problems/thermal/cooling_exact.hpp"

namespace dlpverify::thermal {

namespace {

// Point p of N on the sequence frac((p + ½) g): g = 1 gives the even grid, irrational g a
// low-discrepancy sequence uncorrelated with it.
double spread(Eigen::Index p, double g) {
  const double x = (static_cast<double>(p) + 0.5) * g;
  return x - std::floor(x);
}
constexpr double kGolden = 0.6180339887498949;  // (√5 − 1)/2
constexpr double kSilver = 0.4142135623730951;  // √2 − 1

}  // namespace

CoolingProblem::CoolingProblem(std::string case_name, const CoolingPhysics& physics, const CoolingPopulation& population,
                               std::optional<MemberRange> held)
    : case_name_(std::move(case_name)),
      physics_(physics),
      population_(population),
      held_(held.value_or(MemberRange{0, population.particles})) {
  for (Eigen::Index p = held_.first; p < held_.first + held_.count; ++p) {
    const Rates r = rates(p);
    alpha_.push_back(r.alpha);
    beta_.push_back(r.beta);
  }
  if (closed_form_kind() != Exact::none) provide<ClosedForm>(*this);
  provide<LinearDecay>(*this);
  provide<CaseReport>(*this);
  provide<MemberNoun>(*this);
  provide<ExchangeDescription>(*this);
  provide<InitialMembers>(*this);
}

CoolingProblem::Rates CoolingProblem::rates(Eigen::Index p) const {
  const CoolingPopulation& q = population_;
  const double d = q.d_min + (q.d_max - q.d_min) * (static_cast<double>(p) + 0.5) / q.particles;
  const double emissivity = q.emissivity_min + (q.emissivity_max - q.emissivity_min) * spread(p, kGolden);
  const double per_capacity = 6.0 / (physics_.density * physics_.heat_capacity * d);  // a_s/(m C) of a sphere
  return {physics_.h_c * per_capacity, emissivity * kStefanBoltzmann * per_capacity};
}

double CoolingProblem::theta0(Eigen::Index p) const {
  const CoolingPopulation& q = population_;
  return q.theta0_min + (q.theta0_max - q.theta0_min) * spread(p, kSilver);
}

State CoolingProblem::initial_members(Eigen::Index first, Eigen::Index count) const {
  State state(count, 1);
  for (Eigen::Index p = 0; p < count; ++p) state(p, 0) = theta0(first + p);
  return state;
}

// dθ/dt = −α (θ − θ_o) − β (θ⁴ − θ_s⁴)
void CoolingProblem::rhs(double /*t*/, Eigen::Index first, int count, const double* const* y, double* const* dydt) const {
  const double theta_o = physics_.theta_gas;
  const double theta_s4 = std::pow(physics_.theta_surroundings, 4);
  std::vector<double> scratch;
  const auto [alpha, beta] = rates_of(first, count, scratch);
  for (int i = 0; i < count; ++i) {
    const double theta = y[0][i];
    const double theta2 = theta * theta;
    dydt[0][i] = -alpha[i] * (theta - theta_o) - beta[i] * (theta2 * theta2 - theta_s4);
  }
}

void CoolingProblem::linear_decay(Eigen::Index first, int count, double* const* lambda) const {
  std::vector<double> scratch;
  const double* alpha = rates_of(first, count, scratch).first;
  for (int i = 0; i < count; ++i) lambda[0][i] = alpha[i];
}

std::pair<const double*, const double*> CoolingProblem::rates_of(Eigen::Index first, int count,
                                                                 std::vector<double>& scratch) const {
  if (first >= held_.first && first + count <= held_.first + held_.count)
    return {alpha_.data() + (first - held_.first), beta_.data() + (first - held_.first)};
  scratch.resize(2 * static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const Rates r = rates(first + i);
    scratch[static_cast<std::size_t>(i)] = r.alpha;
    scratch[static_cast<std::size_t>(count + i)] = r.beta;
  }
  return {scratch.data(), scratch.data() + count};
}

// Which closed form the physics has (docs/model.md §7.3): radiation alone (into θ_s > 0 or 0), or
// convection and radiation into θ_o = θ_s = 0; none otherwise.
CoolingProblem::Exact CoolingProblem::closed_form_kind() const {
  if (physics_.h_c == 0.0) return physics_.theta_surroundings > 0.0 ? Exact::radiation : Exact::radiation_to_vacuum;
  if (physics_.theta_gas == 0.0 && physics_.theta_surroundings == 0.0) return Exact::bernoulli;
  return Exact::none;
}

State CoolingProblem::solution(Eigen::Index first, const State& initial, double tau) const {
  const Exact kind = closed_form_kind();
  State out(initial.rows(), 1);
  const double theta_s = physics_.theta_surroundings;
  for (Eigen::Index p = 0; p < initial.rows(); ++p) {
    const Rates r = rates(first + p);
    const double theta0 = initial(p, 0), alpha = r.alpha, beta = r.beta;
    switch (kind) {
      case Exact::bernoulli: out(p, 0) = convection_and_radiation_to_zero(theta0, alpha, beta, tau); break;
      case Exact::radiation: out(p, 0) = radiation_to_surroundings(theta0, beta, theta_s, tau); break;
      default: out(p, 0) = radiation_to_vacuum(theta0, beta, tau); break;
    }
  }
  return out;
}

std::string CoolingProblem::formula() const {
  switch (closed_form_kind()) {
    case Exact::bernoulli:
      return "docs/model.md §7.3: theta = [(theta0^-3 + beta/alpha) exp(3 alpha t) - beta/alpha]^(-1/3) (Bernoulli)";
    case Exact::radiation:
      return "docs/model.md §7.3: beta t = F(theta0) - F(theta), F with ln and atan, theta by a GSL root solve";
    case Exact::radiation_to_vacuum: return "docs/model.md §7.3: theta = theta0 (1 + 3 beta theta0^3 t)^(-1/3)";
    default: return "no closed form with convection and radiation to warm surroundings (CVODE)";
  }
}

nlohmann::json CoolingProblem::parameters() const {
  const CoolingPopulation& q = population_;
  return {{"h_c", {{"value", physics_.h_c}, {"unit", "W/(m^2 K)"}}},
          {"theta_gas", {{"value", physics_.theta_gas}, {"unit", "K"}}},
          {"theta_surroundings", {{"value", physics_.theta_surroundings}, {"unit", "K"}}},
          {"density", {{"value", physics_.density}, {"unit", "kg/m^3"}}},
          {"heat_capacity", {{"value", physics_.heat_capacity}, {"unit", "J/(kg K)"}}},
          {"stefan_boltzmann", {{"value", kStefanBoltzmann}, {"unit", "W/(m^2 K^4)"}}},
          {"particles", q.particles},
          {"diameter", {{"min", q.d_min}, {"max", q.d_max}, {"unit", "m"}}},
          {"emissivity", {{"min", q.emissivity_min}, {"max", q.emissivity_max}}},
          {"theta0", {{"min", q.theta0_min}, {"max", q.theta0_max}, {"unit", "K"}}}};
}

ProblemDescription CoolingProblem::description() const {
  Eigen::ArrayXd alpha(members()), beta(members());
  for (Eigen::Index p = 0; p < members(); ++p) {
    const Rates r = rates(p);
    alpha[p] = r.alpha;
    beta[p] = r.beta;
  }
  return {"cooling",
          {{"h_c", physics_.h_c, "W/(m^2 K)"}, {"theta_gas", physics_.theta_gas, "K"},
           {"theta_surroundings", physics_.theta_surroundings, "K"}, {"density", physics_.density, "kg/m^3"},
           {"heat_capacity", physics_.heat_capacity, "J/(kg K)"}, {"stefan_boltzmann", kStefanBoltzmann, "W/(m^2 K^4)"}},
          {{"equation", "dT/dt = -alpha (T - theta_gas) - beta (T^4 - theta_surroundings^4)"}},
          {{{"alpha", "1/s"}, alpha}, {{"beta", "1/(s K^3)"}, beta}}};
}

// How far the population cooled, and how stiff it is: the largest Δt-free rate |∂f/∂θ| = α + 4βθ³
// at the start, which bounds the explicit and fixed-point steps. Each particle's terms: α + 4βθ0³,
// θ0 and θ at the end.
std::vector<MemberReduction> CoolingProblem::diagnostic_reductions() const {
  return {MemberReduction::max, MemberReduction::sum, MemberReduction::sum};
}

Eigen::ArrayXXd CoolingProblem::member_terms(Eigen::Index first, const State& initial, const State& finest,
                                             double /*t_end*/) const {
  Eigen::ArrayXXd terms(initial.rows(), 3);
  for (Eigen::Index p = 0; p < initial.rows(); ++p) {
    const double theta = initial(p, 0);
    const Rates r = rates(first + p);
    terms(p, 0) = r.alpha + 4.0 * r.beta * theta * theta * theta;
  }
  terms.col(1) = initial.col(0);
  terms.col(2) = finest.col(0);
  return terms;
}

nlohmann::json CoolingProblem::diagnostics(const std::vector<double>& reduced, double /*t_end*/) const {
  const double n = static_cast<double>(members());
  return {{"temperature_start_mean_K", reduced[1] / n},
          {"temperature_end_mean_K", reduced[2] / n},
          {"fastest_rate_per_s", reduced[0]}};
}

}  // namespace dlpverify::thermal
