// Test support: the DLP model's per-particle views (one particle's step, one particle's ODE
// residual) expressed through the problem-independent API, so the tests of the DLP model keep
// asserting per particle what they asserted before the harness became generic.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/solution_features.hpp"
#include "harness/ode_residual.hpp"
#include "problems/dlp/problem.hpp"

namespace dlpverify::test {

using namespace dlpverify::dlp;

// A DlpProblem on any physics and cloud, with its own Case (DlpProblem keeps a pointer to it).
struct PhysicsProblem {
  Case test_case;
  std::unique_ptr<DlpProblem> problem;
  PhysicsProblem(const Physics& physics, Cloud initial, double t0 = 0.0, exact::ParticleSolution solution = nullptr)
      : test_case{"test", "", physics.terms, solution, "", {}} {
    problem = std::make_unique<DlpProblem>(test_case, physics.parameters, std::move(initial), t0);
  }
  const DlpProblem& operator*() const { return *problem; }
};

// A cloud of n particles with speeds, temperatures and masses spread over what the cases reach.
inline Cloud varied_cloud(int n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double m0 = Parameters{}.mass0();
  Cloud cloud(n);
  for (int p = 0; p < n; ++p) {
    const double scale = std::pow(10.0, 2.0 * u(random));  // speeds 0.01 … 100 m/s
    cloud.set_particle(p, {u(random), u(random), u(random), scale * u(random), scale * u(random), scale * u(random),
                           900.0 + 600.0 * u(random), m0 * (0.55 + 0.45 * u(random))});
  }
  return cloud;
}

inline Cloud one_particle(const ParticleState& y) {
  Cloud cloud(1);
  cloud.set_particle(0, y);
  return cloud;
}

// One step of a tableau for one particle, through the block integrator.
template <const auto& Tableau>
void step_particle(const Physics& physics, double t, double dt, ParticleState& y) {
  const PhysicsProblem p(physics, one_particle(y));
  ExplicitRungeKutta<Tableau> method("test");
  State state = p.problem->initial_state();
  method.advance(*p.problem, state, t, dt, 1);
  y = Cloud(state).particle(0);
}

// A problem as it is, but without kinks: the per-particle residual checks every τ it is given
// (the tests choose their τ away from apexes themselves), as the audit's would not.
class WithoutKinks final : public Problem, public ClosedForm, public TimeScale {
 public:
  explicit WithoutKinks(const Problem& p) : p_(p) {
    if (p.capability<ClosedForm>()) provide<ClosedForm>(*this);
    if (p.capability<TimeScale>()) provide<TimeScale>(*this);
  }
  std::string name() const override { return p_.name(); }
  std::vector<Field> fields() const override { return p_.fields(); }
  std::vector<Variable> variables() const override { return p_.variables(); }
  Eigen::Index members() const override { return p_.members(); }
  double initial_time() const override { return p_.initial_time(); }
  State initial_state() const override { return p_.initial_state(); }
  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    p_.rhs(t, first, count, y, dydt);
  }
  State solution(Eigen::Index first, const State& initial, double tau) const override {
    return p_.capability<ClosedForm>()->solution(first, initial, tau);
  }
  std::string formula() const override { return p_.capability<ClosedForm>()->formula(); }
  double time_scale(Eigen::Index member, const double* y, double tau) const override {
    return p_.capability<TimeScale>()->time_scale(member, y, tau);
  }

 private:
  const Problem& p_;
};

// The relative ODE residual of a closed form, group by group (harness/ode_residual.hpp).
struct ParticleResidual {
  double position = 0.0, velocity = 0.0, temperature = 0.0, mass = 0.0;
  double step = 0.0, time_scale = 0.0;
  int non_finite = 0;
  // The largest residual; NaN if any member's or group's is (a closed form that returned NaN fails).
  double max() const {
    double largest = 0.0;
    for (double r : {position, velocity, temperature, mass}) {
      if (std::isnan(r)) return r;
      largest = std::max(largest, r);
    }
    return non_finite > 0 ? std::numeric_limits<double>::quiet_NaN() : largest;
  }
};

inline ParticleResidual cloud_residual(exact::ParticleSolution solution, const Physics& physics, const Cloud& initial,
                                       double tau) {
  const PhysicsProblem p(physics, initial, 0.0, solution);
  const OdeResidual r = ode_residual(WithoutKinks(*p.problem), p.problem->initial_state(), tau);
  ParticleResidual out;
  const std::vector<Variable> variables = p.problem->variables();
  // field_groups: the variables first, then T and m as groups of their own where not measured.
  std::vector<int> first_fields;
  for (const Variable& v : variables) first_fields.push_back(v.first_field);
  for (int f : {TEMPERATURE, MASS})
    if (std::find(first_fields.begin(), first_fields.end(), f) == first_fields.end()) first_fields.push_back(f);
  for (std::size_t g = 0; g < r.groups.size(); ++g) {
    const int f = first_fields[g];
    (f == X ? out.position : f == VX ? out.velocity : f == TEMPERATURE ? out.temperature : out.mass) = r.groups[g];
  }
  out.step = r.step;
  out.time_scale = r.time_scale;
  out.non_finite = r.non_finite;
  return out;
}

inline ParticleResidual particle_residual(exact::ParticleSolution solution, const Physics& physics,
                                          const ParticleState& y0, double tau) {
  return cloud_residual(solution, physics, one_particle(y0), tau);
}

}  // namespace dlpverify::test
