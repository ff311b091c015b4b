#include "problems/spheres/collision_rule.hpp"

#include <cmath>

namespace dlpverify::events {

namespace {

double dot(const double x[3], const double y[3]) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
void cross(const double x[3], const double y[3], double out[3]) {
  out[0] = x[1] * y[2] - x[2] * y[1];
  out[1] = x[2] * y[0] - x[0] * y[2];
  out[2] = x[0] * y[1] - x[1] * y[0];
}

}  // namespace

void collide(const CollisionModel& model, const double n[3], SphereKinematics& a, SphereKinematics& b) {
  // Relative velocity of the contact points (eq. 18): v_ab,c = v_a − v_b − (R_a ω_a + R_b ω_b) × n.
  double spin[3], spin_x_n[3], vc[3];
  for (int k = 0; k < 3; ++k) spin[k] = a.radius * a.w[k] + b.radius * b.w[k];
  cross(spin, n, spin_x_n);
  for (int k = 0; k < 3; ++k) vc[k] = a.v[k] - b.v[k] - (model.smooth() ? 0.0 : spin_x_n[k]);
  const double vn = dot(vc, n);
  if (vn >= 0.0) return;  // receding at the contact: no impulse
  // Normal impulse (eqs. 16–17): J_n = −(1 + e) v_ab,c·n / B2, B2 = 1/m_a + 1/m_b.
  const double b2 = 1.0 / a.mass + 1.0 / b.mass;
  const double jn = -(1.0 + model.restitution) * vn / b2;
  double j[3] = {jn * n[0], jn * n[1], jn * n[2]};

  if (!model.smooth()) {
    // Tangent (eq. 15) and tangential impulse: sticking (eq. 22) unless μ J_n is too small (eqs. 19, 23).
    double vt[3];
    for (int k = 0; k < 3; ++k) vt[k] = vc[k] - n[k] * vn;
    const double vt_norm = std::sqrt(dot(vt, vt));
    if (vt_norm > 0.0) {
      const double b1 = 3.5 * b2;  // eq. 21, solid spheres: I = (2/5) m R²
      const double stick = -(1.0 + model.tangential_restitution) * vt_norm / b1;
      const double slide = -model.friction * jn;
      const double jt = model.friction < (1.0 + model.tangential_restitution) * vt_norm / (jn * b1) ? slide : stick;
      for (int k = 0; k < 3; ++k) j[k] += jt * vt[k] / vt_norm;
    }
    // Rotation (eqs. 11–12, the document's signs): I_a Δω_a = −(R_a n) × J, I_b Δω_b = (R_b n) × (−J);
    // both are −R n × J. (The author's code flips the sign for sphere a; at μ = 0 it never matters.)
    double n_x_j[3];
    cross(n, j, n_x_j);
    const double ia = 0.4 * a.mass * a.radius * a.radius, ib = 0.4 * b.mass * b.radius * b.radius;
    for (int k = 0; k < 3; ++k) {
      a.w[k] -= a.radius * n_x_j[k] / ia;
      b.w[k] -= b.radius * n_x_j[k] / ib;
    }
  }
  // Translation (eqs. 9–10): m_a Δv_a = J, m_b Δv_b = −J.
  for (int k = 0; k < 3; ++k) {
    a.v[k] += j[k] / a.mass;
    b.v[k] -= j[k] / b.mass;
  }
}

}  // namespace dlpverify::events
