// docs/model.md §4.1 — vacuum / similarity solution (no drag, no gravity).
//
//   ODE:    dx/dt = v,  dv/dt = 0
//   exact:  x(τ) = x0 + v0 τ,  v(τ) = v0      (τ = t − t0)
//
// For the lattice cloud launched with v0 = ξ u_s î this is x = ξ u_s t î: the cloud dilates
// linearly in time. T and m are constant (their equations are off).
#pragma once

#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp::exact {

inline ParticleState similarity(const Physics&, const ParticleState& y0, double tau) {
  ParticleState y = y0;
  for (int i = 0; i < 3; ++i) y[X + i] = y0[X + i] + y0[VX + i] * tau;
  return y;
}

}  // namespace dlpverify::dlp::exact
