// A closed form applied to a whole cloud: every particle from its own initial state.
#pragma once

#include "problems/dlp/cloud.hpp"
#include "problems/dlp/parameters.hpp"

namespace dlpverify::dlp::exact {

// A per-particle closed form: the state at τ = t − t0 from the state at t0.
using ParticleSolution = ParticleState (*)(const Physics&, const ParticleState& y0, double tau);

Cloud evaluate(ParticleSolution solution, const Physics& physics, const Cloud& initial, double tau);
// The same from a state's rows (N × 8), without wrapping it in a cloud (no copy).
Cloud evaluate(ParticleSolution solution, const Physics& physics, const State& initial, double tau);

}  // namespace dlpverify::dlp::exact
