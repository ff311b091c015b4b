/// @file
/// The initial state of some members alone, built from their global indices without the whole
/// population's: a rank's share under mpirun asks the problem for its own members (docs/mpi.md),
/// so no rank holds the whole initial state. A capability (problem.hpp): without it a share is
/// sliced from the whole initial state.
#pragma once

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// The initial state of members first … first + count − 1 alone.
class InitialMembers : public Capability {
 public:
  /// Rows first … first + count − 1 of initial_state(), bit for bit.
  virtual State initial_members(Eigen::Index first, Eigen::Index count) const = 0;
};

}  // namespace dlpverify
