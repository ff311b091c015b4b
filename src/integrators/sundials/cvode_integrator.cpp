#include "integrators/sundials/cvode_integrator.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_diag.h>
#include <cvode/cvode_ls.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "dlpverify/reference.hpp"
#include "sundials/population_vector.hpp"
#include "sundials/sundials_support.hpp"
#include "dlpverify/errors.hpp"
#include "harness/distribution.hpp"
#include "io/format.hpp"

namespace dlpverify {

std::vector<double> absolute_tolerances(const Problem& problem, const State& initial, double rtol) {
  std::vector<double> atol = field_scales(problem, initial);
  for (double& a : atol) a *= rtol;
  return atol;
}

// Declaration order is destruction order reversed: CVODE's memory goes first, the context last.
struct CvodeIntegrator::Solver {
  sun::Context context;
  sun::ErrorLog log;              // CVODE's messages, at a stable address (heap)
  sun::ProblemRhsData rhs;        // the user data of problem_rhs, likewise
  sunindextype length = 0;        // F·N of the state this solver was built for
  sun::Vector atol;               // per-entry absolute tolerances
  sun::NonlinearSolver nonlinear; // Adams: fixed-point iteration
  sun::LinearSolver linear;       // BDF with SPGMR
  sun::CvodeMemory memory;
};

void check_cvode_settings(const CvodeSettings& settings) {
  // Any tolerance below 1 is taken: a reference estimates its own error at its rtol / 10, down to
  // 1e-15. What a user may ask of the method under test is the caller's rule.
  if (!std::isfinite(settings.rtol) || settings.rtol <= 0.0 || settings.rtol >= 1.0)
    throw InputError("relative tolerance", value_text(settings.rtol), "must lie in (0, 1)");
  if (settings.max_steps < 1 || settings.max_steps > kMostCvodeSteps)
    throw InputError("CVODE step limit", std::to_string(settings.max_steps), "must lie in [1, 1e9]");
  if (!(settings.max_step >= 0.0)) throw InputError("largest step", value_text(settings.max_step), "must be non-negative");
  if (settings.atol)
    for (double a : *settings.atol)
      if (!(a >= 0.0)) throw InputError("absolute tolerance", value_text(a), "must be non-negative");
}

CvodeIntegrator::CvodeIntegrator(CvodeSettings settings) : settings_(std::move(settings)) {
  check_cvode_settings(settings_);
}

CvodeIntegrator::~CvodeIntegrator() = default;
CvodeIntegrator::CvodeIntegrator(CvodeIntegrator&&) noexcept = default;
CvodeIntegrator& CvodeIntegrator::operator=(CvodeIntegrator&&) noexcept = default;

void CvodeIntegrator::advance(const Problem& problem, State& state, double t0, double dt, long steps) {
  statistics_ = SolverStatistics{};
  // A rank without members still takes part in every sum of the others (across_ranks).
  if (!sun::advance_has_work(dt, steps, settings_.across_ranks ? 1 : state.rows())) return;
  integrate(problem, state, t0, t0 + static_cast<double>(steps) * dt, dt);
}

void CvodeIntegrator::solve(const Problem& problem, State& state, double t_from, double t_to) {
  statistics_ = SolverStatistics{};
  if (!(t_to > t_from)) throw InputError("duration", value_text(t_to - t_from), "must be positive");
  if (state.rows() == 0 && !settings_.across_ranks) return;
  integrate(problem, state, t_from, t_to, settings_.max_step);
}

void CvodeIntegrator::integrate(const Problem& problem, State& state, double t0, double t_final, double max_step) {
  using sun::FlagFamily;
  check_shape(problem, state, "state");
  const Eigen::Index particles = state.rows();
  const int fields = static_cast<int>(state.cols());
  const auto length = static_cast<sunindextype>(particles) * fields;
  const bool openmp = settings_.openmp_vector;
  // Across ranks, an agreement before any vector exists (harness/distribution.hpp): a rank that
  // failed before this solve stops every rank here rather than inside a sum of the vector.
  if (settings_.across_ranks) distribution().any(false);
  const std::vector<double> atol =
      settings_.atol ? *settings_.atol : absolute_tolerances(problem, state, settings_.rtol);
  if (static_cast<int>(atol.size()) != fields)
    throw InputError("absolute tolerance", std::to_string(atol.size()) + " values",
                     "the problem has " + std::to_string(fields) + " fields");

  // The result is written straight into the cloud: y wraps its buffer (no copy, no ownership).
  std::unique_ptr<Solver> fresh;
  Solver* s = solver_.get();
  if (s == nullptr || s->length != length) {
    fresh = std::make_unique<Solver>();
    s = fresh.get();
  }
  const bool compiled = settings_.compiled_vector_operations;
  sun::Vector y = sun::wrap_population(state, openmp, s->context, compiled, settings_.across_ranks);
  s->rhs = {&problem, static_cast<sunindextype>(particles)};
  s->log.clear();

  if (fresh) {
    s->length = length;
    s->memory.reset(CVodeCreate(settings_.method == CvodeMethod::adams ? CV_ADAMS : CV_BDF, s->context));
    sun::check_created(s->memory.get(), "CVodeCreate");
    void* mem = s->memory.get();
    // From here on CVODE reports into the log instead of printing to stderr.
    sun::check_flag(CVodeSetErrHandlerFn(mem, sun::ErrorLog::handler, &s->log), "CVodeSetErrHandlerFn", FlagFamily::cvode);
    sun::check_flag(CVodeInit(mem, sun::problem_rhs, t0, y.get()), "CVodeInit", FlagFamily::cvode, &s->log);
    sun::check_flag(CVodeSetUserData(mem, &s->rhs), "CVodeSetUserData", FlagFamily::cvode, &s->log);
    s->atol.reset(N_VClone(y.get()));  // the same kind of vector as y, spanning the ranks as it does
    sun::check_created(s->atol.get(), "N_VClone");
    if (settings_.method == CvodeMethod::adams) {
      // Non-stiff: functional (fixed-point) iteration needs no Jacobian. CVODE 6's default is
      // Newton, which would fail at the first step without a linear solver.
      s->nonlinear.reset(SUNNonlinSol_FixedPoint(y.get(), 0, s->context));
      sun::check_created(s->nonlinear.get(), "SUNNonlinSol_FixedPoint");
      sun::check_flag(CVodeSetNonlinearSolver(mem, s->nonlinear.get()), "CVodeSetNonlinearSolver", FlagFamily::cvode,
                      &s->log);
    } else if (settings_.linear_solver == CvodeLinearSolver::diagonal) {
      sun::check_flag(CVDiag(mem), "CVDiag", FlagFamily::cvode_diag, &s->log);
    } else {
      s->linear.reset(SUNLinSol_SPGMR(y.get(), SUN_PREC_NONE, 0, s->context));
      sun::check_created(s->linear.get(), "SUNLinSol_SPGMR");
      sun::check_flag(CVodeSetLinearSolver(mem, s->linear.get(), nullptr), "CVodeSetLinearSolver",
                      FlagFamily::cvode_linear, &s->log);
    }
  } else {
    sun::check_flag(CVodeReInit(s->memory.get(), t0, y.get()), "CVodeReInit", FlagFamily::cvode, &s->log);
  }
  void* mem = s->memory.get();

  double* atol_entries = N_VGetArrayPointer(s->atol.get());
  for (int f = 0; f < fields; ++f) std::fill_n(atol_entries + f * particles, particles, atol[static_cast<std::size_t>(f)]);
  sun::check_flag(CVodeSVtolerances(mem, settings_.rtol, s->atol.get()), "CVodeSVtolerances", FlagFamily::cvode, &s->log);
  sun::check_flag(CVodeSetMaxNumSteps(mem, settings_.max_steps), "CVodeSetMaxNumSteps", FlagFamily::cvode, &s->log);
  sun::check_flag(CVodeSetMaxStep(mem, max_step), "CVodeSetMaxStep", FlagFamily::cvode, &s->log);
  sun::check_flag(CVodeSetStopTime(mem, t_final), "CVodeSetStopTime", FlagFamily::cvode, &s->log);
  if (settings_.max_order > 0)
    sun::check_flag(CVodeSetMaxOrd(mem, settings_.max_order), "CVodeSetMaxOrd", FlagFamily::cvode, &s->log);
  if (fresh) solver_ = std::move(fresh);  // fully set up: keep it for the next advance()

  double t_reached = t0;
  const int flag = CVode(mem, t_final, y.get(), &t_reached, CV_NORMAL);

  long steps_taken = 0, rhs_evals = 0, linear_setups = 0, error_test_failures = 0;
  int last_order = 0, current_order = 0;
  double first_step = 0.0, last_step = 0.0, current_step = 0.0, current_time = 0.0;
  long nonlinear_iterations = 0, nonlinear_failures = 0;
  CVodeGetIntegratorStats(mem, &steps_taken, &rhs_evals, &linear_setups, &error_test_failures, &last_order,
                          &current_order, &first_step, &last_step, &current_step, &current_time);
  CVodeGetNonlinSolvStats(mem, &nonlinear_iterations, &nonlinear_failures);
  statistics_ = SolverStatistics{};
  statistics_.steps = steps_taken;
  statistics_.rhs_evals = rhs_evals;
  statistics_.error_test_failures = error_test_failures;
  statistics_.nonlinear_iterations = nonlinear_iterations;
  statistics_.nonlinear_convergence_failures = nonlinear_failures;
  statistics_.linear_solver_setups = linear_setups;
  statistics_.extras = {{"method", std::string(settings_.method == CvodeMethod::adams ? "adams" : "bdf")},
                        {"rtol", settings_.rtol},
                        {"last_order", static_cast<long>(last_order)},
                        {"first_step", first_step},
                        {"last_step", last_step},
                        {"current_time", current_time},
                        {"warnings", s->log.warnings()}};
  if (settings_.method == CvodeMethod::bdf) {
    long jacobian_rhs_evals = 0;
    if (settings_.linear_solver == CvodeLinearSolver::diagonal) {
      CVDiagGetNumRhsEvals(mem, &jacobian_rhs_evals);
    } else {
      long linear_iterations = 0;
      CVodeGetNumLinIters(mem, &linear_iterations);
      CVodeGetNumLinRhsEvals(mem, &jacobian_rhs_evals);
      statistics_.linear_iterations = linear_iterations;
    }
    statistics_.rhs_evals_jacobian = jacobian_rhs_evals;
  }

  sun::check_flag(flag, "CVode", FlagFamily::cvode, &s->log, current_time);
  if (t_reached != t_final) {
    char message[128];
    std::snprintf(message, sizeof message, "CVode failed: returned at t = %.17g s, not at the final time %.17g s",
                  t_reached, t_final);
    throw SolverError(message);
  }
}

SolverStatistics CvodeIntegrator::statistics() const { return statistics_; }

}  // namespace dlpverify
