// What every event must keep, whatever the collision rule computed (docs/model.md §7.2.1). The
// engine checks each event with these and stops the run (SolverError) with the returned reason:
//   pair  momentum m_a v_a + m_b v_b (the impulses on a and b are equal and opposite); kinetic
//         energy, translational plus rotational, never grows (e ≤ 1 and |β0| ≤ 1 only dissipate)
//         and is kept by smooth elastic spheres; afterwards the spheres no longer approach along
//         the normal, v_n' = −e v_n ≥ 0.
//   wall  seen from the wall, an elastic reflection off a wall at rest: the speed relative to the
//         wall is kept, |v' − u| = |v − u|, and the sphere leaves it.
// Each returns an empty string when the event keeps them, else which one broke and by how much.
// Round-off: every comparison allows 1e-12 of the magnitudes involved (one event moves them by a
// few ε).
#pragma once

#include <string>

#include "problems/spheres/collision_rule.hpp"

namespace dlpverify::events {

inline constexpr double kInvariantTolerance = 1e-12;

// a, b before the collision, a2, b2 after it; r = r_a − r_b, the line of centres at contact (of
// any length: the caller computes it afresh, not taking the normal the rule was given).
std::string pair_violation(const CollisionModel& model, const double r[3], const SphereKinematics& a,
                           const SphereKinematics& b, const SphereKinematics& a2, const SphereKinematics& b2);

// The normal velocity component v before and v2 after the hit of a wall moving at u along +axis;
// `lower`: the wall below the sphere on that axis (the sphere leaves it when v2 − u ≥ 0).
std::string wall_violation(double v, double v2, double u, bool lower);

}  // namespace dlpverify::events
