// The exchange file of an external integrator (docs/exchange.md): one HDF5 file holds a problem's
// state, one float64 dataset per field (/fields/x, /fields/vx, …, N members each, member order
// kept), and at its root the description a program needs to set itself up without dlpverify: the
// times, the problem and case, every physical parameter in SI with its unit, the active terms and
// the field list with units. The program's output file has the same layout; only /fields is read.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

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

// A run file (docs/analyze.md): the state a user's program wrote at the end of one run, with the
// run's times when its root carries them (the attributes of this format: t0, dt, steps, t_end).
struct ExchangeRun {
  std::vector<Field> fields;  // from the `fields` attribute, or /fields in name order; units from `unit`
  State state;                // members × fields
  std::optional<Eigen::ArrayXd> ids;  // /fields/id (any number type) when there is one, not a field
  std::optional<double> t0, dt, t_end;  // root attributes, when present
  std::optional<long> steps;
};

// Reads a run file whole: every field float64, one-dimensional, of one length, every value finite.
// Throws ExchangeError naming what is missing or wrong (the first field at fault, the member).
ExchangeRun read_exchange_run(const std::string& path);

// Whether `path` is an HDF5 file (its signature), not whether it is a valid run.
bool is_hdf5_file(const std::string& path);

}  // namespace dlpverify::exchange
