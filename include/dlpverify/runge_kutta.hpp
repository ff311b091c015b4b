/// @file
/// Fixed-step explicit Runge–Kutta methods given by their Butcher tableaux (docs/model.md §3).
///
/// @code{.unparsed}
///   k_i = f(t + c_i Δt, y + Δt Σ_{j<i} a_ij k_j),   y_{n+1} = y_n + Δt Σ_i b_i k_i
/// @endcode
///
/// Members are independent, so a block of kBlock members is carried through all its steps while
/// it sits in L1: the stages are whole-block array loops in structure-of-arrays form, nothing is
/// allocated per step, and the right-hand side is one call per block and stage, never one per
/// member. Written by hand (not Boost.Odeint) because carrying a block through every step is the
/// point; odeint's steppers work on whole states, a step at a time.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "dlpverify/butcher_method.hpp"
#include "dlpverify/first_failure.hpp"
#include "dlpverify/integrator.hpp"
#include "dlpverify/level_stop.hpp"

namespace dlpverify {

/// An explicit Butcher tableau of `Stages` stages: a strictly lower triangular, Σ_i b_i = 1, c_i = Σ_j a_ij.
template <int Stages>
struct ButcherTableau {
  std::array<std::array<double, Stages>, Stages> a;  ///< a_ij, zero on and above the diagonal
  std::array<double, Stages> b;                      ///< weights b_i of y_{n+1} = y_n + Δt Σ_i b_i k_i
  std::array<double, Stages> c;                      ///< nodes c_i: stage i is at t + c_i Δt
  int order;                                         ///< order of accuracy p (global error O(Δt^p))
};

/// A problem's own stepper for a block of members through one built-in Runge–Kutta tableau, its
/// rates inlined into the stage loops (fused_runge_kutta.hpp): `steps` steps from t0 by dt of the
/// `count` members at y[f][0 … count). Empty (run == nullptr) when the problem has none.
struct FusedSteps {
  /// Steps `count` members at y[f][0 … count) `steps` times from t0 by dt, with the constants `rates`.
  void (*run)(const void* rates, double* const* y, int count, double t0, double dt, long steps) = nullptr;
  const void* rates = nullptr;  ///< the problem's constants, for run
  explicit operator bool() const { return run != nullptr; }  ///< whether the problem has a stepper
  /// run(rates, y, count, t0, dt, steps).
  void operator()(double* const* y, int count, double t0, double dt, long steps) const { run(rates, y, count, t0, dt, steps); }
};

/// A capability (problem.hpp) the Runge–Kutta integrators use: the problem's own stepper for a
/// built-in tableau, giving the bits that stepping through Problem::rhs gives.
class FusedStepper : public Capability {
 public:
  /// A stepper with the rates inlined for the tableau at `tableau` (&tableau::midpoint, …) and
  /// blocks of `block` members, or an empty one: the integrator then calls rhs per block and stage.
  virtual FusedSteps fused_steps(const void* tableau, int block) const = 0;
};

/// A capability (problem.hpp): the fields whose rate is zero at every state and time (a
/// particle's temperature when heat transfer is off). An integrator may carry them unchanged, as
/// exact arithmetic would (y + h·0 = y).
class InertFields : public Capability {
 public:
  /// inert[f] for every field f.
  virtual std::vector<bool> inert_fields() const = 0;
};

/// InertFields of `problem`, or no field inert.
inline std::vector<bool> inert_fields(const Problem& problem) {
  if (const InertFields* inert = problem.capability<InertFields>()) return inert->inert_fields();
  return std::vector<bool>(static_cast<std::size_t>(problem.field_count()), false);
}

/// The built-in tableaux (ExplicitRungeKutta<tableau::rk4>, …).
namespace tableau {
/// Forward Euler, order 1.
inline constexpr ButcherTableau<1> euler{{{{0.0}}}, {1.0}, {0.0}, 1};
/// The source paper's RK2, the explicit midpoint rule: y½ = y + (Δt/2) f(y); y' = y + Δt f(y½).
inline constexpr ButcherTableau<2> midpoint{{{{0.0, 0.0}, {0.5, 0.0}}}, {0.0, 1.0}, {0.0, 0.5}, 2};
/// Heun's method (explicit trapezoid), order 2.
inline constexpr ButcherTableau<2> heun{{{{0.0, 0.0}, {1.0, 0.0}}}, {0.5, 0.5}, {0.0, 1.0}, 2};
/// The classical Runge–Kutta method, order 4.
inline constexpr ButcherTableau<4> rk4{{{{0.0, 0.0, 0.0, 0.0}, {0.5, 0.0, 0.0, 0.0}, {0.0, 0.5, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}}},
                                       {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0},
                                       {0.0, 0.5, 0.5, 1.0},
                                       4};
}  // namespace tableau

/// The block buffers of one thread: y, the stage argument and the stage rates k_i, each F fields
/// × kBlock members, with the field pointers the right-hand side takes. An inert field (rate zero
/// everywhere: InertFields) is never staged nor updated: its stage pointer is y's own.
template <int Stages, int Block>
class RungeKuttaBlock {
 public:
  /// Buffers for `fields` fields; inert[f] true: field f is carried unchanged (inert.size() ≥ fields).
  RungeKuttaBlock(int fields, const std::vector<bool>& inert)
      : fields_(fields), storage_(static_cast<std::size_t>((Stages + 2) * fields * Block)) {
    for (int buffer = 0; buffer < Stages + 2; ++buffer) {
      pointers_[buffer].resize(static_cast<std::size_t>(fields));
      for (int f = 0; f < fields; ++f)
        pointers_[buffer][static_cast<std::size_t>(f)] = storage_.data() + (buffer * fields + f) * Block;
    }
    for (int f = 0; f < fields; ++f) {
      if (inert[static_cast<std::size_t>(f)])
        pointers_[1][static_cast<std::size_t>(f)] = pointers_[0][static_cast<std::size_t>(f)];
      else
        active_.push_back(f);
    }
  }
  double* const* y() { return pointers_[0].data(); }      ///< the block's state, F pointers to Block values
  double* const* stage() { return pointers_[1].data(); }  ///< the stage argument y + Δt Σ_j a_ij k_j
  double* const* k(int i) { return pointers_[static_cast<std::size_t>(2 + i)].data(); }  ///< the rates k_i of stage i
  int fields() const { return fields_; }                  ///< F
  /// The fields the step changes, in order.
  const std::vector<int>& active() const { return active_; }

 private:
  int fields_;
  std::vector<double> storage_;
  std::array<std::vector<double*>, Stages + 2> pointers_;
  std::vector<int> active_;
};

/// The stage argument y + Δt Σ_{j<i} a_ij k_j of the fields `active` for `count` members (row i of
/// a tableau, `a`, known at compile time or at run time; k(j) the rates of stage j). Zero a_ij are
/// skipped, and the first term is fused with the copy of y: one pass fewer over the block, the
/// same additions in the same order.
template <class Row, class Rates>
inline void runge_kutta_stage(const Row& a, int i, double dt, const std::vector<int>& active, int count,
                              const double* const* y, double* const* stage, Rates k) {
  for (int f : active) {
    double* s = stage[f];
    const double* yf = y[f];
    bool started = false;
#pragma GCC unroll 8
    for (int j = 0; j < i; ++j) {
      if (a[static_cast<std::size_t>(j)] == 0.0) continue;
      const double h = dt * a[static_cast<std::size_t>(j)];
      const double* kj = k(j)[f];
      if (!started) {
#pragma omp simd
        for (int m = 0; m < count; ++m) s[m] = yf[m] + h * kj[m];
      } else {
#pragma omp simd
        for (int m = 0; m < count; ++m) s[m] += h * kj[m];
      }
      started = true;
    }
    if (!started) std::copy_n(yf, count, s);
  }
}

/// y_{n+1} = y_n + Δt Σ_i b_i k_i over the fields `active` for `count` members, zero b_i skipped.
template <class Weights, class Rates>
inline void runge_kutta_update(const Weights& b, int stages, double dt, const std::vector<int>& active, int count,
                               double* const* y, Rates k) {
#pragma GCC unroll 8
  for (int i = 0; i < stages; ++i) {
    if (b[static_cast<std::size_t>(i)] == 0.0) continue;
    const double h = dt * b[static_cast<std::size_t>(i)];
    for (int f : active) {
      double* yf = y[f];
      const double* ki = k(i)[f];
#pragma omp simd
      for (int m = 0; m < count; ++m) yf[m] += h * ki[m];
    }
  }
}

/// One step of the tableau for the block's `count` members. Zero coefficients are skipped; the
/// tableau is a compile-time constant, so after unrolling the skips cost nothing and the midpoint
/// rule becomes exactly y + (Δt/2) f(y) followed by y + Δt f(y½).
template <const auto& Tableau, int Block>
inline void runge_kutta_step(const Problem& problem, Eigen::Index first, int count, double t, double dt,
                             RungeKuttaBlock<static_cast<int>(Tableau.b.size()), Block>& block) {
  constexpr int stages = static_cast<int>(Tableau.b.size());
  const auto k = [&block](int j) { return block.k(j); };
#pragma GCC unroll 8
  for (int i = 0; i < stages; ++i) {
    double* const* stage = i == 0 ? block.y() : block.stage();  // the first stage is y itself
    if (i > 0) runge_kutta_stage(Tableau.a[static_cast<std::size_t>(i)], i, dt, block.active(), count, block.y(), stage, k);
    problem.rhs(t + Tableau.c[static_cast<std::size_t>(i)] * dt, first, count, stage, block.k(i));
  }
  runge_kutta_update(Tableau.b, stages, dt, block.active(), count, block.y(), k);
}

/// The fixed-step explicit Runge–Kutta method of `Tableau` (e.g. tableau::midpoint) as an
/// Integrator: blocks of kBlock members carried through all their steps, one block per thread.
template <const auto& Tableau>
class ExplicitRungeKutta final : public Integrator, public ButcherMethod {
 public:
  static constexpr int kStages = static_cast<int>(Tableau.b.size());  ///< s, the tableau's stages
  /// Members per block: the block's Stages + 2 buffers of F × 64 doubles stay in L1 (RK4 with the
  /// DLP's 8 fields: 24 KB).
  static constexpr int kBlock = 64;

  /// An integrator that reports itself as `name`.
  explicit ExplicitRungeKutta(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }       ///< as given to the constructor
  int order() const override { return Tableau.order; }      ///< the tableau's order

  /// Integrator::advance: steps (t0 + n dt, n = 0 … steps − 1) of the tableau, block by block;
  /// through the problem's fused stepper when it has one for this tableau (the same bits).
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override {
    check_step(dt, steps);
    const Eigen::Index members = state.rows();
    const int fields = static_cast<int>(state.cols());
    const Eigen::Index blocks = (members + kBlock - 1) / kBlock;
    const std::vector<bool> inert = inert_fields(problem);
    // The problem's fused stepper for this tableau, where it has one: the same bits, fewer passes.
    const FusedStepper* stepper = problem.capability<FusedStepper>();
    const FusedSteps fused = stepper ? stepper->fused_steps(&Tableau, kBlock) : FusedSteps{};
    FirstFailure failure;  // a problem's rhs may throw; it must not leave the parallel region
#pragma omp parallel
    {
      RungeKuttaBlock<kStages, kBlock> block(fields, inert);
#pragma omp for schedule(static)
      for (Eigen::Index b = 0; b < blocks; ++b) {
        const Eigen::Index first = b * kBlock;
        const int count = static_cast<int>(std::min<Eigen::Index>(kBlock, members - first));
        for (int f = 0; f < fields; ++f) std::copy_n(state.col(f).data() + first, count, block.y()[f]);
        try {
          // A full block steps with a compile-time member count (loops without remainders).
          if (fused)
            fused(block.y(), count, t0, dt, steps);
          else if (count == kBlock)
            for (long n = 0; n < steps; ++n) {
              abandon_level_if_stop_requested();
              runge_kutta_step<Tableau, kBlock>(problem, first, kBlock, t0 + static_cast<double>(n) * dt, dt, block);
            }
          else
            for (long n = 0; n < steps; ++n) {
              abandon_level_if_stop_requested();
              runge_kutta_step<Tableau, kBlock>(problem, first, count, t0 + static_cast<double>(n) * dt, dt, block);
            }
        } catch (...) {
          failure.capture();
        }
        for (int f = 0; f < fields; ++f) std::copy_n(block.y()[f], count, state.col(f).data() + first);
      }
    }
    failure.rethrow();
    statistics_ = SolverStatistics{};
    statistics_.steps = steps;
    statistics_.rhs_evals = steps * static_cast<long>(kStages);
  }
  /// Steps and whole-population right-hand-side evaluations (s per step), comparable with CVODE's count.
  SolverStatistics statistics() const override { return statistics_; }
  /// ButcherMethod: the tableau, for a study in extended precision.
  ButcherCoefficients butcher() const override {
    ButcherCoefficients tableau;
    for (int i = 0; i < kStages; ++i) {
      tableau.a.emplace_back(Tableau.a[static_cast<std::size_t>(i)].begin(), Tableau.a[static_cast<std::size_t>(i)].end());
      tableau.b.push_back(Tableau.b[static_cast<std::size_t>(i)]);
      tableau.c.push_back(Tableau.c[static_cast<std::size_t>(i)]);
    }
    return tableau;
  }

 private:
  std::string name_;
  SolverStatistics statistics_;
};

}  // namespace dlpverify
