// Fixed-step explicit Runge–Kutta methods given by their Butcher tableaux (SPEC §3).
//
//   k_i = f(t + c_i Δt, y + Δt Σ_{j<i} a_ij k_j),   y_{n+1} = y_n + Δt Σ_i b_i k_i
//
// The particles of the DLP model do not interact, so each particle is carried through all its
// steps while its state sits in registers: the stages are fused per particle, nothing is allocated
// per step, and the right-hand side is an inlined call, never a virtual one per particle.
// Written by hand (not Boost.Odeint) because fusing per particle across whole-cloud steps is the
// point; odeint's steppers work on whole states.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <string>

#include "integrators/integrator.hpp"

namespace dlpverify {

template <int Stages>
struct ButcherTableau {
  std::array<std::array<double, Stages>, Stages> a;
  std::array<double, Stages> b;
  std::array<double, Stages> c;
  int order;
};

namespace tableau {
// Forward Euler, order 1.
inline constexpr ButcherTableau<1> euler{{{{0.0}}}, {1.0}, {0.0}, 1};
// The seed's RK2 (eqs. 27–30), the explicit midpoint rule: y½ = y + (Δt/2) f(y); y' = y + Δt f(y½).
inline constexpr ButcherTableau<2> midpoint{{{{0.0, 0.0}, {0.5, 0.0}}}, {0.0, 1.0}, {0.0, 0.5}, 2};
// Heun's method (explicit trapezoid), order 2.
inline constexpr ButcherTableau<2> heun{{{{0.0, 0.0}, {1.0, 0.0}}}, {0.5, 0.5}, {0.0, 1.0}, 2};
// The classical Runge–Kutta method, order 4.
inline constexpr ButcherTableau<4> rk4{{{{0.0, 0.0, 0.0, 0.0}, {0.5, 0.0, 0.0, 0.0}, {0.0, 0.5, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}}},
                                       {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0},
                                       {0.0, 0.5, 0.5, 1.0},
                                       4};
}  // namespace tableau

// What a stepper needs of a right-hand side: dy/dt of one particle at time t (ParticleRates is one).
template <class Rates>
concept ParticleRightHandSide = requires(const Rates& f, double t, const ParticleState& y, ParticleState& dydt) {
  f(t, y, dydt);
};

// One step of the tableau for one particle. Zero coefficients are skipped; the tableau is a
// compile-time constant, so after unrolling the skips cost nothing and the midpoint rule becomes
// exactly y + (Δt/2) f(y) followed by y + Δt f(y½).
template <const auto& Tableau, ParticleRightHandSide Rates>
inline void runge_kutta_step(const Rates& f, double t, double dt, ParticleState& y) {
  constexpr int stages = static_cast<int>(Tableau.b.size());
  std::array<ParticleState, stages> k;
#pragma GCC unroll 8
  for (int i = 0; i < stages; ++i) {
    ParticleState stage = y;
#pragma GCC unroll 8
    for (int j = 0; j < i; ++j) {
      if (Tableau.a[i][j] == 0.0) continue;
      const double h = dt * Tableau.a[i][j];
      for (int v = 0; v < kFields; ++v) stage[v] += h * k[j][v];
    }
    f(t + Tableau.c[i] * dt, stage, k[i]);
  }
#pragma GCC unroll 8
  for (int i = 0; i < stages; ++i) {
    if (Tableau.b[i] == 0.0) continue;
    const double h = dt * Tableau.b[i];
    for (int v = 0; v < kFields; ++v) y[v] += h * k[i][v];
  }
}

template <const auto& Tableau>
class ExplicitRungeKutta final : public Integrator {
 public:
  explicit ExplicitRungeKutta(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  int order() const override { return Tableau.order; }

  // Particles advance in blocks of kBlock in lockstep: one particle's steps form a serial chain
  // of dependent sqrt/divide latencies, and interleaving independent particles lets the CPU
  // overlap them. The block stays in L1 for all its steps.
  void advance(const ParticleRates& rates, Cloud& cloud, double t0, double dt, long steps) override {
    const Eigen::Index particles = cloud.size();
    const Eigen::Index blocks = (particles + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static)
    for (Eigen::Index block = 0; block < blocks; ++block) {
      const Eigen::Index first = block * kBlock;
      const int count = static_cast<int>(std::min<Eigen::Index>(kBlock, particles - first));
      std::array<ParticleState, kBlock> y;
      for (int i = 0; i < count; ++i) y[i] = cloud.particle(first + i);
      for (long n = 0; n < steps; ++n) {
        const double t = t0 + static_cast<double>(n) * dt;
        for (int i = 0; i < count; ++i) runge_kutta_step<Tableau>(rates, t, dt, y[i]);
      }
      for (int i = 0; i < count; ++i) cloud.set_particle(first + i, y[i]);
    }
    statistics_ = {{"steps", steps}, {"rhs_evals", steps * static_cast<long>(Tableau.b.size())}};
  }
  // Whole-cloud right-hand-side evaluations, comparable with CVODE's count.
  nlohmann::json statistics() const override { return statistics_; }
  static constexpr int kBlock = 8;

 private:
  std::string name_;
  nlohmann::json statistics_ = nlohmann::json::object();
};

}  // namespace dlpverify
