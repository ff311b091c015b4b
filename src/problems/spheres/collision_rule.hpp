// What a pair collision does to two spheres (docs/model.md §7.2, the seed's appendix eqs. 9–23,
// after Foerster et al. 1994). Smooth elastic spheres by default (e = 1, μ = 0: only the normal
// velocity component is exchanged); the full model adds tangential restitution β0, Coulomb
// friction μ and rotation.
#pragma once

namespace dlpverify::events {

struct CollisionModel {
  double restitution = 1.0;             // e, normal restitution, in [0, 1]
  double tangential_restitution = -1.0; // β0 in [−1, 1]; −1: no tangential impulse when sticking
  double friction = 0.0;                // μ ≥ 0; 0 with β0 = −1: smooth spheres
  bool smooth() const { return friction == 0.0 || tangential_restitution == -1.0; }
};

// One sphere's state as the rule sees it.
struct SphereKinematics {
  double v[3];
  double w[3];  // angular velocity (used by the rough model only)
  double mass, radius;
};

// Applies the impulse of a collision of a and b touching along n = (r_a − r_b)/|r_a − r_b|.
void collide(const CollisionModel& model, const double n[3], SphereKinematics& a, SphereKinematics& b);

}  // namespace dlpverify::events
