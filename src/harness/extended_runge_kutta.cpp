#include "dlpverify/extended_runge_kutta.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "dlpverify/errors.hpp"
#include "dlpverify/first_failure.hpp"
#include "dlpverify/level_stop.hpp"

namespace dlpverify {

namespace {

constexpr double kLargestDenominator = 0x1p24;
constexpr int kBlock = 16;  // members per block: s + 2 buffers of F × 16 double-doubles stay in L1

// The block buffers of one thread: y, the stage argument and the s stage rates, F fields each.
struct Buffers {
  Buffers(int fields, int stages) : storage(static_cast<std::size_t>((stages + 2) * fields * kBlock)) {
    pointers.resize(static_cast<std::size_t>(stages + 2));
    for (int buffer = 0; buffer < stages + 2; ++buffer)
      for (int f = 0; f < fields; ++f)
        pointers[static_cast<std::size_t>(buffer)].push_back(storage.data() + (buffer * fields + f) * kBlock);
  }
  Extended* const* y() { return pointers[0].data(); }
  Extended* const* stage() { return pointers[1].data(); }
  Extended* const* k(int i) { return pointers[static_cast<std::size_t>(2 + i)].data(); }
  std::vector<Extended> storage;
  std::vector<std::vector<Extended*>> pointers;
};

}  // namespace

namespace {

// The fraction exact_coefficient reads `x` as, or nullopt when there is none.
std::optional<Extended> fraction_of(double x) {
  if (!std::isfinite(x) || x == std::floor(x)) return Extended(x);
  // Convergents h_n / k_n of x's continued fraction, its remainders taken in Extended (x is exact
  // in it): h_n = a_n h_{n−1} + h_{n−2}, k_n alike, from h_{−1} = 1, k_{−1} = 0.
  double h_previous = 1.0, k_previous = 0.0, h = std::floor(x), k = 1.0;
  Extended remainder = Extended(x) - h;
  while (remainder != 0.0) {
    const Extended inverse = 1.0 / remainder;
    const double a = std::floor(to_double(inverse));
    remainder = inverse - a;
    const double h_next = a * h + h_previous, k_next = a * k + k_previous;
    if (k_next > kLargestDenominator) break;
    h_previous = h, k_previous = k, h = h_next, k = k_next;
    if (h / k == x) return Extended(h) / k;  // h and k are whole and below 2^53: exact doubles
  }
  return std::nullopt;
}

}  // namespace

Extended exact_coefficient(double x) { return fraction_of(x).value_or(Extended(x)); }

bool read_exactly(const ButcherCoefficients& tableau) {
  const auto fraction = [](double x) { return fraction_of(x).has_value(); };
  for (const std::vector<double>& row : tableau.a)
    if (!std::all_of(row.begin(), row.end(), fraction)) return false;
  return std::all_of(tableau.b.begin(), tableau.b.end(), fraction) &&
         std::all_of(tableau.c.begin(), tableau.c.end(), fraction);
}

ExtendedRungeKutta::ExtendedRungeKutta(const ButcherCoefficients& tableau) {
  const int s = tableau.stages();
  for (int i = 0; i < s; ++i) {
    std::vector<Extended> row;
    for (int j = 0; j < s; ++j) {
      if (j >= i && tableau.a[i][j] != 0.0)
        throw InputError("precision", "extended",
                         "steps explicit Runge-Kutta methods only; this tableau's a_" + std::to_string(i + 1) +
                             std::to_string(j + 1) + " is on or above the diagonal");
      row.push_back(exact_coefficient(tableau.a[i][j]));
    }
    a_.push_back(std::move(row));
    b_.push_back(exact_coefficient(tableau.b[i]));
    c_.push_back(exact_coefficient(tableau.c[i]));
  }
}

void ExtendedRungeKutta::advance(const Problem& problem, ExtendedState& state, const Extended& t0, const Extended& dt,
                                 long steps) const {
  const ExtendedRhs* rhs = problem.capability<ExtendedRhs>();
  if (rhs == nullptr)
    throw InputError("precision", "extended",
                     "needs the case's right-hand side in extended precision, which " + problem.name() + " does not offer");
  const Eigen::Index members = state.rows();
  const int fields = state.cols(), s = stages();
  const Eigen::Index blocks = (members + kBlock - 1) / kBlock;
  FirstFailure failure;  // a problem's rhs may throw; it must not leave the parallel region
#pragma omp parallel
  {
    Buffers buffer(fields, s);
#pragma omp for schedule(static)
    for (Eigen::Index block = 0; block < blocks; ++block) {
      const Eigen::Index first = block * kBlock;
      const int count = static_cast<int>(std::min<Eigen::Index>(kBlock, members - first));
      for (int f = 0; f < fields; ++f) std::copy_n(state.col(f) + first, count, buffer.y()[f]);
      try {
        for (long n = 0; n < steps; ++n) {
          abandon_level_if_stop_requested();
          const Extended t = t0 + static_cast<double>(n) * dt;
          for (int i = 0; i < s; ++i) {
            for (int f = 0; f < fields; ++f)
              for (int m = 0; m < count; ++m) {
                Extended sum = 0.0;
                for (int j = 0; j < i; ++j)
                  if (a_[i][j] != 0.0) sum += a_[i][j] * buffer.k(j)[f][m];
                buffer.stage()[f][m] = buffer.y()[f][m] + dt * sum;
              }
            rhs->extended_rhs(t + c_[i] * dt, first, count, buffer.stage(), buffer.k(i));
          }
          for (int f = 0; f < fields; ++f)
            for (int m = 0; m < count; ++m) {
              Extended sum = 0.0;
              for (int i = 0; i < s; ++i)
                if (b_[i] != 0.0) sum += b_[i] * buffer.k(i)[f][m];
              buffer.y()[f][m] += dt * sum;
            }
        }
      } catch (...) {
        failure.capture();
      }
      for (int f = 0; f < fields; ++f) std::copy_n(buffer.y()[f], count, state.col(f) + first);
    }
  }
  failure.rethrow();
}

}  // namespace dlpverify
