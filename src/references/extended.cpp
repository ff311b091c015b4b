// The extended reference: the problem's ODE solved in Extended (double-double) by Gragg–Bulirsch–
// Stoer extrapolation, so that neither CVODE's tightest tolerance (1e-14) nor double's rounding
// limits what a study can measure. Each macro step H is taken by the modified midpoint rule with
// n_j = 2j substeps, j = 1 … K,
//
//   z_0 = y,  z_1 = z_0 + h f(z_0),  z_{m+1} = z_{m−1} + 2h f(z_m),  T_j1 = ½ (z_n + z_{n−1} + h f(z_n)),
//
// whose error expands in even powers of h = H/n_j, and the T_j1 are extrapolated to h → 0 by
// Aitken–Neville, T_{j,k+1} = T_jk + (T_jk − T_{j−1,k}) / ((n_j / n_{j−k})² − 1): T_KK is of
// order 2K. The macro steps are doubled until two solutions agree to ε_Extended: the finer one is
// the reference, their difference its error estimate (no order assumed, the factor of p = ∞ being
// 1). Written by hand: Boost.Odeint's bulirsch_stoer would take dd_real, but steps whole states,
// not blocks of members through the problem's block right-hand side.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "dlpverify/errors.hpp"
#include "dlpverify/extended.hpp"
#include "dlpverify/first_failure.hpp"
#include "dlpverify/level_stop.hpp"
#include "dlpverify/norms.hpp"
#include "references/source.hpp"

namespace dlpverify::references {

namespace {

constexpr int kColumns = 8;             // K: order 2K = 16
constexpr int kBlock = 16;              // members per block, as the extended Runge–Kutta stepper's
constexpr long kFirstMacroSteps = 8;    // doubled until two solutions agree
constexpr long kMostMacroSteps = 1L << 16;
constexpr double kAgreement = 1e-29;    // relative, per variable: a few units of ε_Extended = 4.9e-32

// F field pointers into `storage`, `count` values each.
struct Fields {
  Fields(int fields, int count) : storage(static_cast<std::size_t>(fields * count)) {
    for (int f = 0; f < fields; ++f) pointers.push_back(storage.data() + f * count);
  }
  Extended* const* p() { return pointers.data(); }
  std::vector<Extended> storage;
  std::vector<Extended*> pointers;
};

// One macro step H from t of the block's `count` members y[f][0 … count), in place.
void macro_step(const ExtendedRhs& rhs, Eigen::Index first, int count, int fields, const Extended& t, const Extended& H,
                Extended* const* y) {
  const auto size = static_cast<std::size_t>(fields * count);
  std::vector<std::vector<Extended>> table(kColumns, std::vector<Extended>(size));  // T_jk, row j of the tableau
  Fields previous(fields, count), current(fields, count), next(fields, count), rate(fields, count);
  for (int j = 1; j <= kColumns; ++j) {
    const int n = 2 * j;
    const Extended h = H / static_cast<double>(n);
    for (int f = 0; f < fields; ++f) std::copy_n(y[f], count, previous.p()[f]);
    rhs.extended_rhs(t, first, count, previous.p(), rate.p());
    for (int f = 0; f < fields; ++f)
      for (int m = 0; m < count; ++m) current.p()[f][m] = previous.p()[f][m] + h * rate.p()[f][m];
    for (int step = 1; step < n; ++step) {
      rhs.extended_rhs(t + static_cast<double>(step) * h, first, count, current.p(), rate.p());
      for (int f = 0; f < fields; ++f)
        for (int m = 0; m < count; ++m) next.p()[f][m] = previous.p()[f][m] + 2.0 * h * rate.p()[f][m];
      std::swap(previous.storage, current.storage), std::swap(previous.pointers, current.pointers);
      std::swap(current.storage, next.storage), std::swap(current.pointers, next.pointers);
    }
    rhs.extended_rhs(t + H, first, count, current.p(), rate.p());
    std::vector<Extended> row(size);
    for (int f = 0; f < fields; ++f)
      for (int m = 0; m < count; ++m)
        row[static_cast<std::size_t>(f * count + m)] =
            0.5 * (current.p()[f][m] + previous.p()[f][m] + h * rate.p()[f][m]);
    // Aitken–Neville: row k of column j from column j − 1's (table[k] holds T_{j−1,k+1}).
    for (int k = 1; k < j; ++k) {
      // 1 / ((n_j / n_{j−k})² − 1) = n_{j−k}² / (n_j² − n_{j−k}²), whole numbers divided in Extended.
      const double coarser = 2.0 * (j - k);
      const Extended factor = Extended(coarser * coarser) / (static_cast<double>(n) * n - coarser * coarser);
      std::vector<Extended> extrapolated(size);
      for (std::size_t i = 0; i < size; ++i)
        extrapolated[i] = row[i] + (row[i] - table[static_cast<std::size_t>(k - 1)][i]) * factor;
      table[static_cast<std::size_t>(k - 1)] = std::move(row);
      row = std::move(extrapolated);
    }
    table[static_cast<std::size_t>(j - 1)] = row;
  }
  const std::vector<Extended>& best = table[kColumns - 1];
  for (int f = 0; f < fields; ++f)
    for (int m = 0; m < count; ++m) y[f][m] = best[static_cast<std::size_t>(f * count + m)];
}

const ExtendedRhs& extended_rhs(const Problem& problem) {
  if (const ExtendedRhs* rhs = problem.capability<ExtendedRhs>()) return *rhs;
  throw InputError("reference", "extended",
                   "needs the case's right-hand side in extended precision, which " + problem.name() + " does not offer");
}

// `state` from τ = from to τ = to (t0 the problem's) in `macro_steps` macro steps.
void extrapolate(const Problem& problem, ExtendedState& state, double from, double to, long macro_steps) {
  const ExtendedRhs& rhs = extended_rhs(problem);
  const Extended t0 = Extended(problem.initial_time()) + from;
  const Extended H = (Extended(to) - from) / static_cast<double>(macro_steps);
  const Eigen::Index members = state.rows();
  const int fields = state.cols();
  const Eigen::Index blocks = (members + kBlock - 1) / kBlock;
  FirstFailure failure;
#pragma omp parallel
  {
    Fields y(fields, kBlock);
#pragma omp for schedule(static)
    for (Eigen::Index b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * kBlock;
      const int count = static_cast<int>(std::min<Eigen::Index>(kBlock, members - first));
      for (int f = 0; f < fields; ++f) std::copy_n(state.col(f) + first, count, y.p()[f]);
      try {
        for (long step = 0; step < macro_steps; ++step) {
          abandon_level_if_stop_requested();
          macro_step(rhs, first, count, fields, t0 + static_cast<double>(step) * H, H, y.p());
        }
      } catch (...) {
        failure.capture();
      }
      for (int f = 0; f < fields; ++f) std::copy_n(y.p()[f], count, state.col(f) + first);
    }
  }
  failure.rethrow();
}

class ExtendedReference final : public ReferenceSource {
 public:
  Reference compute(const Problem& problem, const State& initial, double t_end,
                    const std::vector<Variable>& variables) const override {
    const auto start = std::chrono::steady_clock::now();
    extended_rhs(problem);
    long macro_steps = kFirstMacroSteps;
    ExtendedState coarse(initial);
    extrapolate(problem, coarse, 0.0, t_end, macro_steps);
    for (;;) {
      ExtendedState fine(initial);
      extrapolate(problem, fine, 0.0, t_end, 2 * macro_steps);
      std::vector<double> estimate;
      bool agreed = true;
      for (const Variable& variable : variables) {
        const ErrorNorms difference = error_norms(coarse, fine, variable);
        estimate.push_back(difference.l2);
        agreed = agreed && difference.l2 <= kAgreement * difference.reference_l2;
      }
      macro_steps *= 2;
      if (agreed || macro_steps >= kMostMacroSteps) {
        Reference reference;
        reference.state = fine.high();
        reference.extended = std::make_shared<const ExtendedState>(std::move(fine));
        reference.kind = reference_kind_name(ReferenceKind::extended);
        char detail[200];
        std::snprintf(detail, sizeof detail,
                      "Gragg-Bulirsch-Stoer extrapolation (order %d) in double-double, %ld macro steps, error "
                      "estimated against %ld",
                      2 * kColumns, macro_steps, macro_steps / 2);
        reference.detail = detail;
        reference.error_estimate = std::move(estimate);
        reference.statistics = {{"macro_steps", macro_steps}, {"wall_s", seconds_since(start)}};
        return reference;
      }
      coarse = std::move(fine);
    }
  }

  std::function<State(double tau)> trajectory(const Problem& problem, const State& initial) const override {
    struct Continued {
      ExtendedState state;
      double tau = 0.0;
    };
    auto last = std::make_shared<Continued>(Continued{ExtendedState(initial), 0.0});
    return [&problem, last](double tau) {
      if (tau > last->tau) {
        extrapolate(problem, last->state, last->tau, tau, kFirstMacroSteps * 8);
        last->tau = tau;
      }
      return last->state.high();
    };
  }

  // As tight as the arithmetic: no tighter reference exists.
  std::optional<ReferenceSettings> tightened(double) const override { return std::nullopt; }
};

}  // namespace

std::unique_ptr<ReferenceSource> extended_source() { return std::make_unique<ExtendedReference>(); }

}  // namespace dlpverify::references
