// The initial state of some members alone, built from their global indices without the whole
// population's: a rank's slab under mpirun asks the problem for its own members
// (harness/sub_population.hpp, docs/mpi.md), so no rank holds the whole initial state.
#pragma once

#include "dlpverify/problem.hpp"

namespace dlpverify {

class InitialMembers : public Capability {
 public:
  // Rows first … first + count − 1 of initial_state(), bit for bit.
  virtual State initial_members(Eigen::Index first, Eigen::Index count) const = 0;
};

}  // namespace dlpverify
