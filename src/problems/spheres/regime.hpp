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

// Bounds on collisions per sphere during the motion, from one-axis compressions to r = 2 measured
// here (docs/model.md §7.2): 0.05–0.44 collisions per sphere gave (r² + 2)/3 within 1%, 0.6 within
// 2.1%, 0.95 within 3.2%; 51–92 gave r^(2/3) (of the centres' compression) within 0.8%.
inline constexpr double kCollisionlessBelow = 0.3;
inline constexpr double kCollisionDominatedAbove = 50.0;
Regime classify(double collisions_per_sphere);

// The expected mean free path of a dilute hard-sphere gas, λ = 1 / (√2 π σ² n), n = N / V.
double mean_free_path(int spheres, double radius, double volume);

}  // namespace dlpverify::compress
