// A cloud of particles in structure-of-arrays form, and the lattice cloud of docs/model.md §2.
//
// The state is one N × 8 column-major Eigen array: each field (x, y, z, vx, vy, vz, T, m) is a
// contiguous column, so whole-field expressions vectorise and the whole cloud is one contiguous
// buffer a SUNDIALS N_Vector can wrap without copying.
#pragma once

#include "dlpverify/eigen.hpp"
#include <string>

#include "dlpverify/problem.hpp"
#include "problems/dlp/parameters.hpp"
#include "problems/dlp/particle.hpp"

namespace dlpverify::dlp {

// The problem-independent state type (N × F, column-major) with F = kFields columns.
using CloudArray = State;

class Cloud {
 public:
  Cloud() = default;
  explicit Cloud(Eigen::Index particles) : state_(particles, kFields) {}
  explicit Cloud(State state) : state_(std::move(state)) {}

  Eigen::Index size() const { return state_.rows(); }
  CloudArray& state() { return state_; }
  const CloudArray& state() const { return state_; }

  ParticleState particle(Eigen::Index p) const {
    ParticleState y;
    for (int f = 0; f < kFields; ++f) y[f] = state_(p, f);
    return y;
  }
  void set_particle(Eigen::Index p, const ParticleState& y) {
    for (int f = 0; f < kFields; ++f) state_(p, f) = y[f];
  }

 private:
  CloudArray state_;
};

enum class Shape { sphere, shell };

// Which lattice points P = (i, j, k)·Δ make the cloud: inner ≤ ‖(i, j, k)‖ ≤ outer, inclusive,
// compared on squared integers so the counts of docs/model.md §2 are exact.
struct Lattice {
  Shape shape = Shape::sphere;
  int outer = 100;  // R_out
  int inner = 1;    // sphere: 1; shell: R_out − 5 (docs/model.md §2)
  double spacing = 1e-4;  // Δ [m]
  bool z_axis_only = false;  // keep only the points on the z axis (i = j = 0): vertical motion

  static int default_inner(Shape shape, int outer) { return shape == Shape::sphere ? 1 : std::max(outer - 5, 0); }
};

// Number of lattice points in the cloud, without building it.
long long count_lattice_points(const Lattice& lattice);

// The launch state of docs/model.md §2 at t0 = r_s0 / u_s, r_s0 = R_out Δ: each particle at its lattice
// point x0, with the similarity velocity v0 = ξ u_s î = x0 / t0, temperature T_p0 and mass m0.
struct Launch {
  double expansion_speed = 100.0;  // u_s [m/s]
};
double initial_time(const Lattice& lattice, const Launch& launch);  // t0 = R_out Δ / u_s
Cloud make_cloud(const Lattice& lattice, const Launch& launch, const Parameters& parameters);
// Points first … first + count − 1 of make_cloud's cloud alone, bit for bit, without the others.
Cloud make_cloud_members(const Lattice& lattice, const Launch& launch, const Parameters& parameters, Eigen::Index first,
                         Eigen::Index count);

// ‖x‖ of every particle of a state (N × the cloud's fields), correctly rounded.
Eigen::ArrayXd distance_from_centre(const State& state);
// ξ = ‖x‖ / r_s(t) of every particle of a cloud at time t, r_s = u_s t.
Eigen::ArrayXd similarity_coordinate(const Cloud& cloud, double t, const Launch& launch);

std::string to_string(Shape shape);

}  // namespace dlpverify::dlp
