// Exact event times of free flight (docs/model.md §7.2): a pair of spheres, and a sphere against a
// plane wall moving at constant speed. Both return +inf when the event never happens.
#pragma once

#include <cmath>
#include <limits>

namespace dlpverify::events {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

// Earliest t ≥ 0 with ‖r + v t‖ = σ, r = r_a − r_b, v = v_a − v_b, σ = R_a + R_b.
// With b = r·v, c = r·r − σ², the roots are t = (−b ∓ √(b² − v² c)) / v². The earlier one is
// written as t = c / (−b + √(b² − v² c)) — the same number, without the cancellation of −b − √…
// when the spheres graze (b² ≫ v² c). Receding pairs (b ≥ 0) never collide. A pair that
// overlaps by round-off (c < 0) while approaching collides now (t = 0).
inline double pair_time(double rx, double ry, double rz, double vx, double vy, double vz, double sigma) {
  const double b = rx * vx + ry * vy + rz * vz;
  const double v2 = vx * vx + vy * vy + vz * vz;
  const double c = rx * rx + ry * ry + rz * rz - sigma * sigma;
  const double disc = b * b - v2 * c;
  if (b >= 0.0 || disc < 0.0) return kNever;
  return std::fmax(c / (-b + std::sqrt(disc)), 0.0);
}

// Time until a sphere's surface meets a wall: `gap` is the distance from the sphere's surface to
// the wall now (≥ 0, or a round-off hair below), `closing` the speed at which that distance
// shrinks (particle velocity minus wall velocity, along the wall's inward-facing normal).
inline double wall_time(double gap, double closing) {
  if (closing <= 0.0) return kNever;
  return std::fmax(gap, 0.0) / closing;
}

}  // namespace dlpverify::events
