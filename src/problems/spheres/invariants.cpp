#include "problems/spheres/invariants.hpp"

#include <cmath>

#include "io/format.hpp"

namespace dlpverify::events {

namespace {

double norm(const double x[3]) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); }

// ½ m |v|² + ½ I |ω|², I = (2/5) m R² (solid spheres).
double energy(const SphereKinematics& s) {
  return 0.5 * s.mass * (s.v[0] * s.v[0] + s.v[1] * s.v[1] + s.v[2] * s.v[2]) +
         0.2 * s.mass * s.radius * s.radius * (s.w[0] * s.w[0] + s.w[1] * s.w[1] + s.w[2] * s.w[2]);
}

}  // namespace

std::string pair_violation(const CollisionModel& model, const double r[3], const SphereKinematics& a,
                           const SphereKinematics& b, const SphereKinematics& a2, const SphereKinematics& b2) {
  const double distance = norm(r);
  const double n[3] = {r[0] / distance, r[1] / distance, r[2] / distance};
  double change[3];
  for (int k = 0; k < 3; ++k) change[k] = a2.mass * a2.v[k] + b2.mass * b2.v[k] - (a.mass * a.v[k] + b.mass * b.v[k]);
  const double momentum_scale = a.mass * (norm(a.v) + norm(a2.v)) + b.mass * (norm(b.v) + norm(b2.v));
  if (norm(change) > kInvariantTolerance * momentum_scale)
    return printf_string("the pair's momentum changed by %.3e kg m/s (of %.3e): the impulses on the two spheres are "
                         "not equal and opposite",
                         norm(change), 0.5 * momentum_scale);

  const double e = energy(a) + energy(b), e2 = energy(a2) + energy(b2);
  const bool conserving = model.restitution == 1.0 && model.smooth();
  if (conserving ? std::fabs(e2 - e) > kInvariantTolerance * e : e2 > e * (1.0 + kInvariantTolerance))
    return printf_string("the pair's kinetic energy went from %s to %s J (relative change %+.3e): %s",
                         shortest_text(e).c_str(), shortest_text(e2).c_str(),
                         e2 / e - 1.0,
                         conserving ? "smooth elastic spheres keep it" : "a collision with e <= 1, |beta0| <= 1 cannot add to it");

  const double vn = (a.v[0] - b.v[0]) * n[0] + (a.v[1] - b.v[1]) * n[1] + (a.v[2] - b.v[2]) * n[2];
  const double vn2 = (a2.v[0] - b2.v[0]) * n[0] + (a2.v[1] - b2.v[1]) * n[1] + (a2.v[2] - b2.v[2]) * n[2];
  const double speed_scale = norm(a.v) + norm(b.v) + norm(a2.v) + norm(b2.v);
  if (vn2 < -kInvariantTolerance * speed_scale)
    return printf_string("the spheres still approach after the collision: normal relative velocity %.6g m/s, %.6g "
                         "before (it must become -e v_n >= 0)",
                         vn2, vn);
  return {};
}

std::string wall_violation(double v, double v2, double u, bool lower) {
  const double closing = v - u, leaving = v2 - u;  // the sphere's velocity seen from the wall
  const double scale = std::fabs(v) + std::fabs(v2) + std::fabs(u);
  if (std::fabs(std::fabs(leaving) - std::fabs(closing)) > kInvariantTolerance * scale)
    return printf_string("the speed relative to the wall (moving at %.6g m/s) went from %s to %s m/s: an elastic "
                         "reflection keeps it (v' = 2u - v)",
                         u, shortest_text(std::fabs(closing)).c_str(), shortest_text(std::fabs(leaving)).c_str());
  if (lower ? leaving < -kInvariantTolerance * scale : leaving > kInvariantTolerance * scale)
    return printf_string("the sphere still approaches the wall (moving at %.6g m/s) after the hit: velocity %.6g m/s "
                         "relative to it",
                         u, leaving);
  return {};
}

}  // namespace dlpverify::events
