#include "problems/spheres/regime.hpp"

#include <cmath>
#include <numbers>

namespace dlpverify::compress {

std::string to_string(Regime regime) {
  switch (regime) {
    case Regime::collisionless: return "collisionless";
    case Regime::transitional: return "transitional";
    case Regime::collision_dominated: return "collision-dominated";
  }
  return "?";
}

Regime classify(double collisions_per_sphere) {
  if (collisions_per_sphere <= kCollisionlessBelow) return Regime::collisionless;
  if (collisions_per_sphere >= kCollisionDominatedAbove) return Regime::collision_dominated;
  return Regime::transitional;
}

double mean_free_path(int spheres, double radius, double volume) {
  const double sigma = 2.0 * radius;
  return volume / (std::numbers::sqrt2 * std::numbers::pi * sigma * sigma * spheres);
}

}  // namespace dlpverify::compress
