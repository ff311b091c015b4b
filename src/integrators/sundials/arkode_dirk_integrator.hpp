// A diagonally implicit Runge–Kutta table of the user's (DIRK, SDIRK, ESDIRK: a_ij = 0 for j > i)
// at a fixed step, through ARKStep with the table as its implicit one (fe = NULL, fi = f):
//
//   z_i = y_n + Δt Σ_{j≤i} a_ij f(t_n + c_j Δt, z_j),   y_{n+1} = y_n + Δt Σ_i b_i f(t_n + c_i Δt, z_i)
//
// each stage solved by Newton's method with matrix-free GMRES (arkstep_support.hpp). The Newton
// iteration stops when its correction's weighted RMS norm is at most kNewtonTolerance, with the
// weights 1/(kNewtonRelative |y| + kNewtonRelative ‖y₀‖_max): a correction below 1e-10 of the
// state, and Newton's last iterate far closer (its error falls quadratically). Measured: steps of
// backward Euler, the implicit midpoint rule and Alexander's SDIRK agree with their closed forms to
// 1e-11 (unit.dirk_tableau), where the steps' own errors are 1e-3 to 1e-5; a tighter test
// (1e-10 weights) did not converge within 10 iterations on drag's SDIRK studies. A step whose Newton iteration does not converge is not retried with
// a smaller step (the step is the study's): it fails the advance with a SolverError.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dlpverify/integrator.hpp"

namespace dlpverify {

inline constexpr double kNewtonRelative = 1e-8;    // the weights' relative and absolute scale
inline constexpr double kNewtonTolerance = 1e-2;   // ARKStepSetNonlinConvCoef: the correction's WRMS bound
inline constexpr int kNewtonIterations = 10;       // ARKStepSetMaxNonlinIters

// The Butcher coefficients of a diagonally implicit method, s stages.
struct DirkTable {
  std::vector<double> c, b;
  std::vector<std::vector<double>> a;  // s × s, zero above the diagonal
};

class ArkodeDirkIntegrator final : public Integrator {
 public:
  // `name` as name() returns it, `order` the method's claimed order.
  ArkodeDirkIntegrator(std::string name, int order, DirkTable table);
  std::string name() const override { return name_; }
  int order() const override { return order_; }
  // Throws SolverError when ARKODE fails, a Newton iteration does not converge, or the steps taken
  // are not exactly `steps`.
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override;
  // Of the last advance(): steps, rhs_evals, the Newton and GMRES counts, and newton_tolerance.
  SolverStatistics statistics() const override { return statistics_; }

 private:
  std::string name_;
  int order_;
  DirkTable table_;
  SolverStatistics statistics_;
};

}  // namespace dlpverify
