// The population shared out over processes (MPI ranks, docs/mpi.md): which members this process
// holds, and the few exchanges between processes a study needs. Members are independent, so the
// only communication is in the reductions over the population (the norms' and the case
// diagnostics' block partials, the CVODE reference's field scales and counts) and, for the
// per-particle file only, in the report (rank 0 gathers the finest state and the reference).
//
// Serially (no distribution installed) one process holds every member and every exchange is the
// identity. src/mpi/ installs one over MPI_COMM_WORLD when the command runs under mpirun.
//
// Every exchange is collective: each process calls the same exchanges in the same order.
#pragma once

#include <string>
#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

class Distribution {
 public:
  virtual ~Distribution() = default;
  virtual int rank() const = 0;   // this process, 0 … ranks() − 1
  virtual int ranks() const = 0;  // processes sharing the population
  // Every process's `local` values, concatenated in rank order, on every process.
  virtual std::vector<double> all_gathered(const std::vector<double>& local) const = 0;
  // Every process's rows of `local` stacked in rank order (member order), on rank 0; empty elsewhere.
  virtual State gathered_on_root(const State& local) const = 0;
  // Rank 0's `text` on every process.
  virtual std::string from_root(const std::string& text) const = 0;

  // Reductions built on all_gathered, evaluated in rank order on every process (so every process
  // gets the same bits). max is NaN once any process's value is NaN.
  double max(double local) const;
  long sum(long local) const;
  long max(long local) const;
  bool any(bool local) const;
};

// The installed distribution, or the serial one (rank 0 of 1).
const Distribution& distribution();
// Installs `d` (nullptr: serial again); it must outlive every use.
void install_distribution(const Distribution* d);

// Members first … first + count − 1, held by one process.
struct MemberRange {
  Eigen::Index first = 0;
  Eigen::Index count = 0;
};

// The members `rank` of `ranks` holds: whole blocks of kSumBlock members (the norms' blocks,
// harness/compensated_sum.hpp) by global index, contiguous and in rank order, the blocks shared
// as evenly as they go. Whole blocks make each process's block partials the serial run's.
MemberRange own_members(Eigen::Index members, int rank, int ranks);
// This process's members under the installed distribution.
MemberRange own_members(Eigen::Index members);

}  // namespace dlpverify
