// CVODE (SUNDIALS) behind the Integrator interface: the high-accuracy reference of
// docs/model.md §3, for any problem.
//
// The whole population is one N_Vector of length F·N that wraps the state's column-major N × F
// buffer (field f of member p at f·N + p) without copying; CVODE writes its answer straight back.
// Its sums go by (field, block of members) (sundials/population_vector.hpp), over every rank
// when the settings say the state is a rank's share.
//   Adams (non-stiff): variable order 1–12, fixed-point nonlinear iteration, no Jacobian.
//   BDF (stiff):       variable order 1–5, Newton with a diagonal approximate Jacobian (CVDiag)
//                      or matrix-free GMRES (SPGMR). Never a dense F·N × F·N matrix.
// solve() integrates t_from → t_to with the settings' largest step and a stop time at the end,
// so the result lands on the final time exactly; advance() (a study level) takes the level's
// dt as the largest step. name() "cvode", order() 0 (variable order).
#pragma once

#include <memory>
#include <optional>

#include <vector>

#include "dlpverify/integrator.hpp"

namespace dlpverify {

enum class CvodeMethod { adams, bdf };
enum class CvodeLinearSolver { diagonal, spgmr };  // BDF's Newton iteration only

struct CvodeSettings {
  double rtol = 1e-10;
  // Absolute tolerance per field; when empty, rtol × field_scales(problem, initial state).
  std::optional<std::vector<double>> atol;
  // Largest step of solve() [s]; 0: none. advance() takes its dt instead.
  double max_step = 0.0;
  CvodeMethod method = CvodeMethod::adams;
  CvodeLinearSolver linear_solver = CvodeLinearSolver::diagonal;
  long max_steps = 100000;     // CVodeSetMaxNumSteps, per solve
  int max_order = 0;           // CVodeSetMaxOrd; 0: CVODE's own (12 for Adams, 5 for BDF)
  bool openmp_vector = false;  // N_VNew_OpenMP with omp_get_max_threads(), else serial
  // Vector arithmetic compiled here instead of Debian's unoptimised SUNDIALS loops (4–5× faster
  // overall; see nvector_compiled.hpp). Off only to compare against SUNDIALS' own vectors.
  bool compiled_vector_operations = true;
  // The state is this rank's share of a population spread over MPI ranks (docs/mpi.md): the
  // vector's sums span every rank, so each rank takes the serial run's steps. Every rank must
  // then call advance() and solve() together, a rank without members too. Set by the command.
  bool across_ranks = false;
};

// Refuses settings CVODE cannot honour, before any work: a "relative tolerance" outside
// (0, 1), a "CVODE step limit" outside [1, kMostCvodeSteps], a negative "largest step" or
// "absolute tolerance". InputError naming the quantity.
void check_cvode_settings(const CvodeSettings& settings);

// rtol × field_scales(problem, initial): fields have very different magnitudes (DLP: 1e-4 m,
// 100 m/s, 1500 K, 1e-9 kg), so one scalar atol would be meaningless for some of them.
std::vector<double> absolute_tolerances(const Problem& problem, const State& initial, double rtol);

class CvodeIntegrator final : public Integrator {
 public:
  explicit CvodeIntegrator(CvodeSettings settings = {});
  ~CvodeIntegrator() override;
  CvodeIntegrator(CvodeIntegrator&&) noexcept;
  CvodeIntegrator& operator=(CvodeIntegrator&&) noexcept;

  std::string name() const override { return "cvode"; }
  int order() const override { return 0; }
  // Throws SolverError (with CVODE's flag name, e.g. CV_TOO_MUCH_WORK) when CVODE gives up.
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override;
  // From t_from to t_to with settings().max_step as the largest step (0: no limit).
  void solve(const Problem& problem, State& state, double t_from, double t_to);
  // Of the last advance(): steps, rhs_evals, error_test_failures, nonlinear_iterations,
  // nonlinear_convergence_failures, last_order, last_step, current_time, …
  SolverStatistics statistics() const override;

  const CvodeSettings& settings() const { return settings_; }

 private:
  struct Solver;  // the SUNDIALS objects, kept across calls on states of the same size
  void integrate(const Problem& problem, State& state, double t_from, double t_to, double max_step);
  CvodeSettings settings_;
  std::unique_ptr<Solver> solver_;
  SolverStatistics statistics_;
};

}  // namespace dlpverify
