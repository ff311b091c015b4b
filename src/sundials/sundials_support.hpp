// Owning SUNDIALS objects, and the one error boundary between SUNDIALS and dlpverify.
//
// Like sundials::Context (sundials_context.hpp), every SUNDIALS handle here is move-only RAII:
// a std::unique_ptr whose deleter calls the matching free (N_VDestroy, CVodeFree, ARKStepFree,
// SUNLinSolFree, …), so no early return or exception leaks solver memory (SUNDIALS' own
// cv_kpr.cpp does). Destroy a context last: declare it before the objects made in it.
//
// Errors: SUNDIALS' own error printing is replaced by an ErrorLog that keeps the message, and a
// negative flag becomes one dlpverify::SolverError line such as
//   CVode failed: CV_TOO_MUCH_WORK at t = 1.234e-03 s (At t = 0.00123, mxstep steps taken …)
#pragma once

#include <cstdio>  // before arkode_butcher.h, which uses FILE without including it (6.4.1)

#include <arkode/arkode_butcher.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include "dlpverify/problem.hpp"

namespace dlpverify::sun {

// ---- owners ---------------------------------------------------------------------------------

// A SUNContext (SUNContext_Create / SUNContext_Free). Move-only.
class Context {
 public:
  Context();  // throws SolverError when SUNContext_Create fails
  ~Context();
  Context(Context&& other) noexcept;
  Context& operator=(Context&& other) noexcept;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  SUNContext get() const { return context_; }
  operator SUNContext() const { return context_; }

 private:
  SUNContext context_ = nullptr;
};

struct VectorDeleter {
  void operator()(N_Vector v) const noexcept;
};
struct CvodeMemoryDeleter {
  void operator()(void* cvode_mem) const noexcept;
};
struct ArkstepMemoryDeleter {
  void operator()(void* arkode_mem) const noexcept;
};
struct LinearSolverDeleter {
  void operator()(SUNLinearSolver solver) const noexcept;
};
struct NonlinearSolverDeleter {
  void operator()(SUNNonlinearSolver solver) const noexcept;
};
struct ButcherTableDeleter {
  void operator()(ARKodeButcherTable table) const noexcept;
};

using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using CvodeMemory = std::unique_ptr<void, CvodeMemoryDeleter>;     // from CVodeCreate
using ArkstepMemory = std::unique_ptr<void, ArkstepMemoryDeleter>;  // from ARKStepCreate
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;
using NonlinearSolver = std::unique_ptr<std::remove_pointer_t<SUNNonlinearSolver>, NonlinearSolverDeleter>;
using ButcherTable = std::unique_ptr<std::remove_pointer_t<ARKodeButcherTable>, ButcherTableDeleter>;

// A new vector of `length` entries: our compiled vector (nvector_compiled.hpp), threaded or not;
// with `compiled` false, SUNDIALS' own N_VNew_OpenMP (omp_get_max_threads() threads) or serial.
Vector make_vector(sunindextype length, bool openmp, SUNContext context, bool compiled = true);
// A vector that uses `data` (length entries) without copying or owning it (likewise).
Vector wrap_vector(double* data, sunindextype length, bool openmp, SUNContext context, bool compiled = true);

// ---- errors ---------------------------------------------------------------------------------

// Collects what SUNDIALS would otherwise print to stderr. Install `handler` with
// CVodeSetErrHandlerFn / ARKStepSetErrHandlerFn and this log (at a stable address) as its data.
class ErrorLog {
 public:
  // Matches CVErrHandlerFn and ARKErrHandlerFn. Errors (code < 0) replace the last error;
  // warnings (code > 0, e.g. "t + h = t") are only counted.
  static void handler(int error_code, const char* module, const char* function, char* message, void* log);

  void clear();
  const std::string& last_error() const { return last_error_; }  // empty when none
  long warnings() const { return warnings_; }

 private:
  std::string last_error_;
  long warnings_ = 0;
};

// Which GetReturnFlagName translates a flag (the flag values of the families overlap).
enum class FlagFamily {
  cvode,         // CVodeGetReturnFlagName: CV_TOO_MUCH_WORK, …
  cvode_linear,  // CVodeGetLinReturnFlagName: CVLS_* (CVodeSetLinearSolver)
  cvode_diag,    // CVDiagGetReturnFlagName: CVDIAG_* (CVDiag)
  arkode,        // ARKStepGetReturnFlagName: ARK_* (ARKStep*)
  arkode_linear, // ARKStepGetLinReturnFlagName: ARKLS_* (ARKStepSetLinearSolver)
  generic,       // anything else: the number only
};

// Name of a SUNDIALS return flag, e.g. "CV_TOO_MUCH_WORK" (the C functions return a malloc'd
// string, which this frees).
std::string flag_name(FlagFamily family, int flag);

// Throws SolverError for a negative flag:
//   "<call> failed: <FLAG_NAME>[ at t = <time> s][ (<last error logged>)]"
// Non-negative flags (success, CV_TSTOP_RETURN, warnings) return normally.
void check_flag(int flag, const char* call, FlagFamily family = FlagFamily::generic, const ErrorLog* log = nullptr,
                std::optional<double> time = std::nullopt);

// Throws SolverError "<call> failed: returned NULL" when a SUNDIALS constructor returned nothing.
void check_created(const void* created, const char* call);

// The arguments of Integrator::advance a SUNDIALS adapter accepts: a positive, finite dt and a
// non-negative step count. Returns false when there is nothing to do (no steps or no particles).
bool advance_has_work(double dt, long steps, long particles);

// ---- the right-hand side --------------------------------------------------------------------

// The user data of problem_rhs: the problem and its population size N.
struct ProblemRhsData {
  const Problem* problem = nullptr;
  sunindextype members = 0;
};

// f(t, y) for the whole population as one vector of length F·N in the problem's column-major
// layout (field f of member p at f·N + p), handed to Problem::rhs in blocks of members (OpenMP
// across blocks for large populations). Matches CVRhsFn and ARKRhsFn.
int problem_rhs(double t, N_Vector y, N_Vector ydot, void* problem_rhs_data);

}  // namespace dlpverify::sun
