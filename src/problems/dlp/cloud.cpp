#include "problems/dlp/cloud.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace dlpverify::dlp {

namespace {
// The largest k ≥ 0 with k² ≤ n (n ≥ 0): the double's root, corrected to the exact integer.
long long integer_sqrt(long long n) {
  auto k = static_cast<long long>(std::sqrt(static_cast<double>(n)));
  while (k * k > n) --k;
  while ((k + 1) * (k + 1) <= n) ++k;
  return k;
}

// How many k have i² + j² + k² ≤ n, for a = i² + j²: |k| ≤ √(n − a).
long long column_points(long long a, long long n) { return a > n ? 0 : 2 * integer_sqrt(n - a) + 1; }

// Points of plane i: column by column (i, j), the k with inner² ≤ r² ≤ outer² are those with
// r² ≤ outer² less those with r² ≤ inner² − 1.
long long plane_points(const Lattice& lattice, long long i) {
  const long long outer2 = static_cast<long long>(lattice.outer) * lattice.outer;
  const long long inner2 = static_cast<long long>(lattice.inner) * lattice.inner;
  const long long plane = lattice.z_axis_only ? 0 : lattice.outer;
  long long count = 0;
  for (long long j = -plane; j <= plane; ++j) {
    const long long a = i * i + j * j;
    count += column_points(a, outer2) - (inner2 > 0 ? column_points(a, std::min(inner2 - 1, outer2)) : 0);
  }
  return count;
}
}  // namespace

// O(R_out²), so the study's memory can be estimated before a cloud of R_out = 2000 (3.4e10
// points, 6.4e10 candidates) is ever enumerated.
long long count_lattice_points(const Lattice& lattice) {
  const long long plane = lattice.z_axis_only ? 0 : lattice.outer;
  long long count = 0;
  for (long long i = -plane; i <= plane; ++i) count += plane_points(lattice, i);
  return count;
}

double initial_time(const Lattice& lattice, const Launch& launch) {
  return lattice.outer * lattice.spacing / launch.expansion_speed;
}

// Plane by plane (i) in parallel, each plane from its offset (the points of the planes before
// it), so the points are in lexicographic (i, j, k) order whatever the threads; the threads also
// first-touch the pages they write. Only the points first … first + count − 1 are kept (row
// p − first), and planes holding none of them are skipped.
Cloud make_cloud_members(const Lattice& lattice, const Launch& launch, const Parameters& parameters, Eigen::Index first,
                         Eigen::Index count) {
  const double t0 = initial_time(lattice, launch);
  const double h = lattice.spacing;
  const double m0 = parameters.mass0();
  const long long outer = lattice.outer;
  const long long outer2 = outer * outer;
  const long long inner2 = static_cast<long long>(lattice.inner) * lattice.inner;
  const long long plane = lattice.z_axis_only ? 0 : outer;
  std::vector<Eigen::Index> offset(static_cast<std::size_t>(2 * plane + 2), 0);
  for (long long i = -plane; i <= plane; ++i)
    offset[static_cast<std::size_t>(i + plane + 1)] = offset[static_cast<std::size_t>(i + plane)] + plane_points(lattice, i);
  const Eigen::Index end = std::min(first + count, offset.back());
  Cloud cloud(std::max<Eigen::Index>(0, end - first));
  auto& s = cloud.state();
#pragma omp parallel for schedule(dynamic)
  for (long long i = -plane; i <= plane; ++i) {
    Eigen::Index p = offset[static_cast<std::size_t>(i + plane)];
    if (p >= end || offset[static_cast<std::size_t>(i + plane + 1)] <= first) continue;
    for (long long j = -plane; j <= plane; ++j)
      for (long long k = -outer; k <= outer; ++k) {
        const long long r2 = i * i + j * j + k * k;
        if (r2 < inner2 || r2 > outer2) continue;
        if (p >= first && p < end) {
          const Eigen::Index row = p - first;
          s(row, X) = static_cast<double>(i) * h;
          s(row, Y) = static_cast<double>(j) * h;
          s(row, Z) = static_cast<double>(k) * h;
          // v0 = ξ u_s î with ξ = ‖x0‖ / (u_s t0): v0 = x0 / t0 (zero at the origin).
          s(row, VX) = s(row, X) / t0;
          s(row, VY) = s(row, Y) / t0;
          s(row, VZ) = s(row, Z) / t0;
          s(row, TEMPERATURE) = parameters.t_particle;
          s(row, MASS) = m0;
        }
        ++p;
      }
  }
  return cloud;
}

Cloud make_cloud(const Lattice& lattice, const Launch& launch, const Parameters& parameters) {
  return make_cloud_members(lattice, launch, parameters, 0, static_cast<Eigen::Index>(count_lattice_points(lattice)));
}

Eigen::ArrayXd distance_from_centre(const State& s) {
  // std::sqrt member by member: correctly rounded, whatever the vector lanes (the build also sets
  // EIGEN_FAST_MATH=0, without which Eigen's array sqrt is an approximation on AVX-512).
  Eigen::ArrayXd r(s.rows());
  for (Eigen::Index p = 0; p < s.rows(); ++p) r[p] = std::sqrt(s(p, X) * s(p, X) + s(p, Y) * s(p, Y) + s(p, Z) * s(p, Z));
  return r;
}

Eigen::ArrayXd similarity_coordinate(const Cloud& cloud, double t, const Launch& launch) {
  return distance_from_centre(cloud.state()) / (launch.expansion_speed * t);
}

std::string to_string(Shape shape) { return shape == Shape::sphere ? "sphere" : "shell"; }

}  // namespace dlpverify::dlp
