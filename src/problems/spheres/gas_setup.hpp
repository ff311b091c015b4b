// The initial gas of a compression run (docs/model.md §7.2): N equal spheres placed uniformly at
// random in a cube without overlap (random sequential insertion), velocity components uniform in
// [−v_max, v_max]. Deterministic given the seed, on every platform: std::mt19937_64's output is
// specified by the standard, and the mapping to [0, 1) is ours (the top 53 bits × 2⁻⁵³) —
// std::uniform_real_distribution's is implementation-defined.
#pragma once

#include <cstdint>

#include "problems/spheres/engine.hpp"

namespace dlpverify::compress {

struct GasSetup {
  int spheres = 60;
  double mass = 1.0;         // kg
  double radius = 0.02;      // m
  double speed_max = 9.0;    // velocity components uniform in [−speed_max, speed_max] m/s
  double edge = 8.0;         // cube edge, walls at ±edge/2 [m]
  // Dense gases: the first N sites of a k × k × k grid filling the cube (k = ⌈N^(1/3)⌉) instead of
  // random insertion, which jams near η ≈ 0.38 and needs far more tries well before that.
  bool lattice = false;
};

// Throws InputError when the spheres do not fit (insertion gives up after 1000 tries per sphere;
// on the lattice, when neighbouring sites are closer than a diameter).
events::Spheres place_gas(const GasSetup& gas, std::uint64_t seed);
events::Box cube(double edge);

// Packing fraction η = N (π/6) σ³ / V of N spheres of radius r in a volume V.
double packing_fraction(int spheres, double radius, double volume);
// The radius that gives packing fraction η in the cube.
double radius_for_packing(int spheres, double packing, double edge);

// One run's seed from the study's seed and the run's index (SplitMix64: runs far apart).
std::uint64_t run_seed(std::uint64_t seed, std::uint64_t run);

}  // namespace dlpverify::compress
