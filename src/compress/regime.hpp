// Which law a compression should follow (docs/model.md §7.2). What decides is how many pair
// collisions each sphere has while the walls move (a Knudsen-like number, the inverse of the
// motion time in mean free times): with far fewer than one, the velocity components never
// exchange energy and each axis keeps its own adiabatic invariant |v_k| L_k; with many, they stay
// equal and the gas follows the monatomic adiabat.
#pragma once

#include <string>

namespace dlpverify::compress {

enum class Regime { collisionless, transitional, collision_dominated };
std::string to_string(Regime regime);

// Bounds on collisions per sphere during the motion, measured here on one-axis compressions:
// ≤ 0.2 follows (r² + 2)/3 and ≥ 50 follows r^(2/3), each within 2% (docs/model.md §7.2).
inline constexpr double kCollisionlessBelow = 0.2;
inline constexpr double kCollisionDominatedAbove = 50.0;
Regime classify(double collisions_per_sphere);

// The expected mean free path of a dilute hard-sphere gas, λ = 1 / (√2 π σ² n), n = N / V.
double mean_free_path(int spheres, double radius, double volume);

}  // namespace dlpverify::compress
