// The members this rank solves under mpirun (docs/mpi.md): a slab of whole norm blocks of the
// whole problem (a SubPopulation, every capability passed through), or the whole problem on one
// rank.
#pragma once

#include <optional>

#include "dlpverify/problem.hpp"
#include "harness/sub_population.hpp"

namespace dlpverify {

class RankShare {
 public:
  explicit RankShare(const Problem& whole);
  const Problem& problem() const { return slab_ ? *slab_ : whole_; }

 private:
  const Problem& whole_;
  std::optional<SubPopulation> slab_;
};

}  // namespace dlpverify
