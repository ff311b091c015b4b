#include "problems/spheres/gas_setup.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "dlpverify/errors.hpp"

namespace dlpverify::compress {

namespace {

// Uniform in [0, 1): the top 53 bits of one 64-bit draw.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double uniform(std::mt19937_64& rng, double low, double high) { return low + (high - low) * unit(rng); }

}  // namespace

std::uint64_t run_seed(std::uint64_t seed, std::uint64_t run) {
  std::uint64_t z = seed + (run + 1) * 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

events::Box cube(double edge) {
  events::Box box;
  for (int k = 0; k < 3; ++k) box.lower[k] = -0.5 * edge, box.upper[k] = 0.5 * edge;
  return box;
}

double packing_fraction(int spheres, double radius, double volume) {
  const double sigma = 2.0 * radius;
  return spheres * std::numbers::pi / 6.0 * sigma * sigma * sigma / volume;
}

double radius_for_packing(int spheres, double packing, double edge) {
  return 0.5 * std::cbrt(6.0 * packing * edge * edge * edge / (std::numbers::pi * spheres));
}

namespace {

std::array<double, 3> random_velocity(std::mt19937_64& rng, double speed_max) {
  std::array<double, 3> v{};
  for (double& c : v) c = uniform(rng, -speed_max, speed_max);
  return v;
}

events::Spheres place_on_lattice(const GasSetup& gas, std::mt19937_64& rng) {
  int k = 1;
  while (k * k * k < gas.spheres) ++k;
  const double spacing = gas.edge / k;
  if (!(spacing > 2.0 * gas.radius))
    throw InputError("sphere radius", std::to_string(gas.radius), "the lattice's sites are closer than a diameter");
  events::Spheres spheres;
  for (int i = 0; i < gas.spheres; ++i) {
    const int site[3] = {i % k, (i / k) % k, i / (k * k)};
    std::array<double, 3> p{};
    for (int a = 0; a < 3; ++a) p[a] = -0.5 * gas.edge + (site[a] + 0.5) * spacing;
    spheres.add(p, random_velocity(rng, gas.speed_max), gas.radius, gas.mass);
  }
  return spheres;
}

}  // namespace

events::Spheres place_gas(const GasSetup& gas, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  if (gas.lattice) return place_on_lattice(gas, rng);
  events::Spheres spheres;
  const double half = 0.5 * gas.edge - gas.radius, min_distance2 = 4.0 * gas.radius * gas.radius;
  if (!(half > 0.0)) throw InputError("sphere radius", std::to_string(gas.radius), "the spheres do not fit in the box");
  // Random sequential insertion jams near η ≈ 0.38 and slows down long before: refused above 0.3.
  const double packing = packing_fraction(gas.spheres, gas.radius, gas.edge * gas.edge * gas.edge);
  if (packing > 0.3)
    throw InputError("sphere radius", std::to_string(gas.radius),
                     "packing fraction " + std::to_string(packing) + " is too dense for random insertion (at most 0.3; a lattice start takes more)");
  for (int i = 0; i < gas.spheres; ++i) {
    std::array<double, 3> p{};
    for (int attempt = 0;; ++attempt) {
      if (attempt == 1000)
        throw InputError("sphere radius", std::to_string(gas.radius),
                         "random insertion found no room for sphere " + std::to_string(i + 1) + " of " +
                             std::to_string(gas.spheres) + " (packing fraction too high)");
      for (double& c : p) c = uniform(rng, -half, half);
      bool free = true;
      for (std::size_t j = 0; j < spheres.size() && free; ++j) {
        const double dx = p[0] - spheres.x[j], dy = p[1] - spheres.y[j], dz = p[2] - spheres.z[j];
        free = dx * dx + dy * dy + dz * dz > min_distance2;
      }
      if (free) break;
    }
    spheres.add(p, random_velocity(rng, gas.speed_max), gas.radius, gas.mass);
  }
  return spheres;
}

}  // namespace dlpverify::compress
