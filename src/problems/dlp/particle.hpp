// The state of one DLP particle (docs/model.md §1): position, velocity, temperature, mass.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace dlpverify::dlp {

// Field order of a particle state and of the cloud's columns.
enum ParticleField : int { X = 0, Y, Z, VX, VY, VZ, TEMPERATURE, MASS };
inline constexpr int kFields = 8;

// One particle's state y = (x, y, z, vx, vy, vz, T, m), or its rate dy/dt.
using ParticleState = std::array<double, kFields>;

// The speed s = ‖v‖ of a particle state (a ParticleState, or a member of a block).
template <class State>
inline auto speed(const State& y) {
  using std::sqrt;  // QD's for an Extended state
  return sqrt(y[VX] * y[VX] + y[VY] * y[VY] + y[VZ] * y[VZ]);
}

}  // namespace dlpverify::dlp
