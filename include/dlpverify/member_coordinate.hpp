/// @file
/// A coordinate that places each member of a population, for the per-member view of a study's
/// errors (format_per_particle, dlpverify/report.hpp): the DLP cloud's similarity coordinate
/// ξ = r / r_s0 at launch. A problem without one has no per-member view.
#pragma once

#include <Eigen/Core>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// Each member's coordinate at the initial state.
class MemberCoordinate : public Capability {
 public:
  /// The coordinates of members first … first + count − 1, in order.
  virtual Eigen::ArrayXd member_coordinate(Eigen::Index first, Eigen::Index count) const = 0;
};

}  // namespace dlpverify
