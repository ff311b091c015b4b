// The exchange file of an external integrator (docs/exchange.md): one HDF5 file holds a problem's
// state, one float64 dataset per field (/fields/x, /fields/vx, …, N members each, member order
// kept), and at its root the description a program needs to set itself up without dlpverify: the
// times, the problem and case, every physical parameter in SI with its unit, the active terms and
// the field list with units. The program's output file has the same layout; only /fields is read.
#pragma once

#include <stdexcept>
#include <string>

#include "dlpverify/problem.hpp"

namespace dlpverify::exchange {

// Raised on the format's version (docs/exchange.md): a change a reader must know of raises it.
inline constexpr int kExchangeVersion = 1;

// The step plan of one level, as the external program is asked to run it.
struct StepPlan {
  double t0 = 0.0;
  double dt = 0.0;
  long steps = 0;
  int threads = 1;
  double t_end() const { return t0 + static_cast<double>(steps) * dt; }  // step n starts at t0 + n·dt
};

// An exchange file that cannot be read, or lacks what it must hold (the message says which and why).
class ExchangeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes `state` (N × F, the problem's fields) and the problem's description to `path`, whole
// columns at a time. Throws ExchangeError when the file cannot be written.
void write_exchange_file(const std::string& path, const Problem& problem, const State& state, const StepPlan& plan);

// Reads the problem's fields from /fields of `path` into `state` (N × F): every field present,
// one-dimensional of length N, numeric and finite; extra datasets and attributes are ignored.
// Throws ExchangeError naming the first field at fault (and, for a non-finite value, the member).
void read_exchange_fields(const std::string& path, const Problem& problem, State& state);

}  // namespace dlpverify::exchange
