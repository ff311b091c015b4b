// The dlpverify command under mpirun (docs/mpi.md): MPI set up for the process's lifetime, the
// population shared out over MPI_COMM_WORLD (harness/distribution.hpp), and one outcome for the
// whole command — the same single error line and exit code as a serial run, from whichever rank
// failed.
//
// No exchange may deadlock on a failed rank: every exchange opens with an agreement (one
// MPI_Allreduce of a status word), and a rank that fails joins the next agreement with its error
// instead of leaving. The others then throw PeerFailed with the failing rank's exit code and line
// (the lowest failing rank's when several fail at once).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "harness/distribution.hpp"

namespace dlpverify::mpi {

// True when a process manager started this process (mpirun: OMPI_COMM_WORLD_SIZE; srun and
// other PMIx launchers: PMIX_RANK): only then is MPI initialised, so the command run on its own
// stays a serial program that never touches MPI.
bool launched_by_mpi();

// How the command ends on every rank.
struct Outcome {
  int code = 0;      // the exit code
  std::string line;  // the error line (without "dlpverify: "); empty when none is to be printed
};

// Thrown by an exchange when another rank failed: its outcome.
class PeerFailed : public std::runtime_error {
 public:
  explicit PeerFailed(Outcome outcome) : std::runtime_error(outcome.line), outcome_(std::move(outcome)) {}
  const Outcome& outcome() const { return outcome_; }

 private:
  Outcome outcome_;
};

class Session final : public Distribution {
 public:
  // MPI_Init_thread (MPI_THREAD_FUNNELED: only the main thread calls MPI, OpenMP threads share a
  // rank's blocks), installs itself as the distribution; ranks other than 0 print nothing (their
  // standard output and error go to /dev/null).
  Session(int& argc, char**& argv);
  ~Session() override;  // MPI_Finalize
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  std::vector<double> all_gathered(const std::vector<double>& local) const override;
  State gathered_on_root(const State& local) const override;
  std::string from_root(const std::string& text) const override;

  // This rank failed: the outcome every rank ends with (the lowest failing rank's code and line).
  Outcome fail(int code, const std::string& line) const;
  // This rank finished its command with `code`: a failure of another rank, else rank 0's code.
  Outcome finish(int code) const;

 private:
  void agree() const;  // throws PeerFailed when a rank failed
  Outcome failure_of(int failed_rank, int code, const std::string& line) const;

  int rank_ = 0, ranks_ = 1;
};

}  // namespace dlpverify::mpi
