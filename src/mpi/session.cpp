#include "mpi/session.hpp"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>

namespace dlpverify::mpi {

namespace {

void check(int status, const char* call) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + call + " failed");
}

// The lowest rank whose status is a failure (its own number), or `ranks` when every rank is well.
int lowest_failed(int own) {
  int lowest = own;
  check(MPI_Allreduce(&own, &lowest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
  return lowest;
}

}  // namespace

bool launched_by_mpi() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

Session::Session(int& argc, char**& argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  // A failed exchange comes back as a status (turned into an exception), never an abort.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
  if (rank_ != 0) {
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr)) std::fflush(nullptr);
  }
  install_distribution(this);
}

Session::~Session() {
  install_distribution(nullptr);
  MPI_Finalize();
}

void Session::agree() const {
  const int lowest = lowest_failed(ranks_);
  if (lowest < ranks_) throw PeerFailed(failure_of(lowest, 0, {}));
}

// Every rank takes part: `failed_rank` sends its code and line, the others receive them.
Outcome Session::failure_of(int failed_rank, int code, const std::string& line) const {
  Outcome outcome{code, line};
  int length = static_cast<int>(line.size());
  check(MPI_Bcast(&outcome.code, 1, MPI_INT, failed_rank, MPI_COMM_WORLD), "MPI_Bcast");
  check(MPI_Bcast(&length, 1, MPI_INT, failed_rank, MPI_COMM_WORLD), "MPI_Bcast");
  outcome.line.resize(static_cast<std::size_t>(length));
  check(MPI_Bcast(outcome.line.data(), length, MPI_CHAR, failed_rank, MPI_COMM_WORLD), "MPI_Bcast");
  return outcome;
}

Outcome Session::fail(int code, const std::string& line) const {
  const int lowest = lowest_failed(rank_);
  return failure_of(lowest, code, line);
}

Outcome Session::finish(int code) const {
  agree();
  Outcome outcome{code, {}};
  check(MPI_Bcast(&outcome.code, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return outcome;
}

std::vector<double> Session::all_gathered(const std::vector<double>& local) const {
  agree();
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks_)), offsets(static_cast<std::size_t>(ranks_));
  check(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  int total = 0;
  for (int r = 0; r < ranks_; ++r) {
    offsets[static_cast<std::size_t>(r)] = total;
    total += counts[static_cast<std::size_t>(r)];
  }
  std::vector<double> all(static_cast<std::size_t>(total));
  check(MPI_Allgatherv(local.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                       MPI_COMM_WORLD),
        "MPI_Allgatherv");
  return all;
}

// Column by column (State is column-major: a field's members are contiguous), rows in rank order.
State Session::gathered_on_root(const State& local) const {
  agree();
  const int rows = static_cast<int>(local.rows());
  std::vector<int> counts(static_cast<std::size_t>(ranks_)), offsets(static_cast<std::size_t>(ranks_));
  check(MPI_Gather(&rows, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
  int total = 0;
  for (int r = 0; r < ranks_; ++r) {
    offsets[static_cast<std::size_t>(r)] = total;
    total += counts[static_cast<std::size_t>(r)];
  }
  State all(rank_ == 0 ? total : 0, local.cols());
  for (Eigen::Index f = 0; f < local.cols(); ++f)
    check(MPI_Gatherv(local.col(f).data(), rows, MPI_DOUBLE, rank_ == 0 ? all.col(f).data() : nullptr, counts.data(),
                      offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD),
          "MPI_Gatherv");
  return all;
}

std::string Session::from_root(const std::string& text) const {
  agree();
  int length = static_cast<int>(text.size());
  check(MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  std::string received = text;
  received.resize(static_cast<std::size_t>(length));
  check(MPI_Bcast(received.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return received;
}

}  // namespace dlpverify::mpi
