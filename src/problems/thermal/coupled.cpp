#include "problems/thermal/coupled.hpp"

#include <cmath>
#include <numbers>

#include <unsupported/Eigen/MatrixFunctions>

namespace dlpverify::thermal {

CoupledSystem::CoupledSystem(std::string case_name, int equations, const CouplingConstants& constants, int members)
    : case_name_(std::move(case_name)), equations_(equations), k_(constants), members_(members) {
  provide<StaggeredBlocks>(*this);
  provide<SweepContraction>(*this);
  provide<ClosedForm>(*this);
  provide<TimeScale>(*this);
  provide<CaseReport>(*this);
  provide<MemberNoun>(*this);
  provide<ExchangeDescription>(*this);
  provide<TimeUnit>(*this);
  provide<InitialMembers>(*this);
}

std::vector<Field> CoupledSystem::fields() const {
  if (equations_ == 2) return {{"w1", "1"}, {"w2", "1"}};
  return {{"w1", "1"}, {"w2", "1"}, {"w3", "1"}, {"v3", "1/s"}};
}

std::vector<Variable> CoupledSystem::variables() const {
  std::vector<Variable> list;
  const std::vector<Field> all = fields();
  for (int f = 0; f < static_cast<int>(all.size()); ++f) list.push_back({all[static_cast<std::size_t>(f)].name, f, 1, all[static_cast<std::size_t>(f)].unit});
  return list;
}

// Member k of N starts on the unit circle (2 × 2) or a twisted curve on the unit 3-sphere (3 × 3)
// at angle φ = 2π (k + ½)/N: every direction of the state space, none on an axis.
State CoupledSystem::initial_members(Eigen::Index first, Eigen::Index count) const {
  State y(count, field_count());
  for (Eigen::Index i = 0; i < count; ++i) {
    const Eigen::Index k = first + i;
    const double phi = 2.0 * std::numbers::pi * (static_cast<double>(k) + 0.5) / static_cast<double>(members_);
    if (equations_ == 2) {
      y(i, 0) = std::cos(phi);
      y(i, 1) = std::sin(phi);
    } else {
      const double psi = 3.0 * phi;
      y(i, 0) = std::cos(phi) * std::cos(psi);
      y(i, 1) = std::cos(phi) * std::sin(psi);
      y(i, 2) = std::sin(phi) * std::cos(psi);
      y(i, 3) = std::sin(phi) * std::sin(psi);
    }
  }
  return y;
}

void CoupledSystem::rhs(double /*t*/, Eigen::Index /*first*/, int count, const double* const* y, double* const* dydt) const {
  if (equations_ == 2) {
    for (int i = 0; i < count; ++i) {
      dydt[0][i] = -y[1][i] / k_.a;  // a ẇ1 + w2 = 0
      dydt[1][i] = -y[0][i] / k_.b;  // b ẇ2 + w1 = 0
    }
    return;
  }
  for (int i = 0; i < count; ++i) {
    dydt[0][i] = -y[1][i] / k_.a;  // a ẇ1 + w2 = 0
    dydt[1][i] = -y[2][i] / k_.b;  // b ẇ2 + w3 = 0
    dydt[2][i] = y[3][i];          // ẇ3 = v3
    dydt[3][i] = -y[0][i] / k_.c;  // c v̇3 + w1 = 0
  }
}

std::vector<FieldBlock> CoupledSystem::staggered_blocks() const {
  if (equations_ == 2) return {{"w1", 0, 1}, {"w2", 1, 1}};
  return {{"w1", 0, 1}, {"w2", 1, 1}, {"w3", 2, 2}};
}

State CoupledSystem::solution(Eigen::Index /*first*/, const State& initial, double tau) const {
  State out(initial.rows(), initial.cols());
  if (equations_ == 2) {
    const double omega = 1.0 / std::sqrt(k_.a * k_.b);
    const double ch = std::cosh(omega * tau), sh = std::sinh(omega * tau);
    const double b_over_a = std::sqrt(k_.b / k_.a);
    out.col(0) = initial.col(0) * ch - initial.col(1) * b_over_a * sh;
    out.col(1) = initial.col(1) * ch - initial.col(0) / b_over_a * sh;
    return out;
  }
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  a(0, 1) = -1.0 / k_.a;
  a(1, 2) = -1.0 / k_.b;
  a(2, 3) = 1.0;
  a(3, 0) = -1.0 / k_.c;
  const Eigen::Matrix4d propagator = (a * tau).exp();
  out.matrix() = initial.matrix() * propagator.transpose();  // each row: y(t)ᵀ = y(0)ᵀ exp(Aτ)ᵀ
  return out;
}

std::string CoupledSystem::formula() const {
  return equations_ == 2 ? "docs/model.md §7.3: w1 = w1(0) cosh(wt) - w2(0) sqrt(b/a) sinh(wt), w = 1/sqrt(ab)"
                         : "docs/model.md §7.3: y(t) = exp(A t) y(0), the 4 x 4 matrix exponential (Eigen)";
}

nlohmann::json CoupledSystem::parameters() const {
  nlohmann::json j = {{"a", k_.a}, {"b", k_.b}, {"members", members_}, {"step_limit", step_limit()}};
  if (equations_ == 3) j["c"] = k_.c;
  return j;
}

ProblemDescription CoupledSystem::description() const {
  return {"coupled",
          {{"a", k_.a, "1"}, {"b", k_.b, "1"}, {"c", k_.c, "1"}},
          {{"equations", equations_ == 2 ? "a w1' + w2 = 0, b w2' + w1 = 0"
                                         : "a w1' + w2 = 0, b w2' + w3 = 0, w3' = v3, c v3' + w1 = 0"}},
          {}};
}

double CoupledSystem::jacobi_radius(double dt) const {
  return equations_ == 2 ? dt / std::sqrt(k_.a * k_.b) : std::cbrt(std::pow(dt, 4) / std::abs(k_.a * k_.b * k_.c));
}

double CoupledSystem::gauss_seidel_radius(double dt) const {
  const double rho = jacobi_radius(dt);
  return equations_ == 2 ? rho * rho : std::pow(rho, 1.5);
}

double CoupledSystem::step_limit() const {
  return equations_ == 2 ? std::sqrt(k_.a * k_.b) : std::pow(std::abs(k_.a * k_.b * k_.c), 0.25);
}

std::string CoupledSystem::jacobi_radius_formula() const {
  return equations_ == 2 ? "dt/sqrt(ab)" : "(dt^4/|abc|)^(1/3)";
}

std::string CoupledSystem::gauss_seidel_radius_formula() const {
  return equations_ == 2 ? "dt^2/(ab)" : "(dt^4/|abc|)^(1/2)";
}

std::string CoupledSystem::step_limit_formula() const { return equations_ == 2 ? "sqrt(ab)" : "|abc|^(1/4)"; }

}  // namespace dlpverify::thermal
