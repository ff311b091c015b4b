#include "sundials/sundials_support.hpp"

#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <cvode/cvode_diag.h>
#include <cvode/cvode_ls.h>
#include <nvector/nvector_openmp.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include <cstdlib>
#include <utility>

#include "dlpverify/errors.hpp"
#include "dlpverify/integrator.hpp"
#include "dlpverify/level_stop.hpp"
#include "sundials/nvector_compiled.hpp"

namespace dlpverify::sun {

// ---- owners ---------------------------------------------------------------------------------

Context::Context() {
  // SUNDIALS 6.x: the first argument is an MPI communicator, NULL without MPI.
  check_flag(SUNContext_Create(nullptr, &context_), "SUNContext_Create");
}

Context::~Context() {
  if (context_ != nullptr) SUNContext_Free(&context_);
}

Context::Context(Context&& other) noexcept : context_(std::exchange(other.context_, nullptr)) {}

Context& Context::operator=(Context&& other) noexcept {
  if (this != &other) {
    if (context_ != nullptr) SUNContext_Free(&context_);
    context_ = std::exchange(other.context_, nullptr);
  }
  return *this;
}

void VectorDeleter::operator()(N_Vector v) const noexcept { N_VDestroy(v); }
void CvodeMemoryDeleter::operator()(void* cvode_mem) const noexcept { CVodeFree(&cvode_mem); }
void ArkstepMemoryDeleter::operator()(void* arkode_mem) const noexcept { ARKStepFree(&arkode_mem); }
void LinearSolverDeleter::operator()(SUNLinearSolver solver) const noexcept { SUNLinSolFree(solver); }
void NonlinearSolverDeleter::operator()(SUNNonlinearSolver solver) const noexcept { SUNNonlinSolFree(solver); }
void ButcherTableDeleter::operator()(ARKodeButcherTable table) const noexcept { ARKodeButcherTable_Free(table); }

Vector make_vector(sunindextype length, bool openmp, SUNContext context, bool compiled) {
  if (compiled) {
    Vector v(new_compiled_vector(length, openmp, context));
    check_created(v.get(), "new_compiled_vector");
    return v;
  }
  Vector v(openmp ? N_VNew_OpenMP(length, omp_get_max_threads(), context) : N_VNew_Serial(length, context));
  check_created(v.get(), openmp ? "N_VNew_OpenMP" : "N_VNew_Serial");
  return v;
}

Vector wrap_vector(double* data, sunindextype length, bool openmp, SUNContext context, bool compiled) {
  if (compiled) {
    Vector v(wrap_compiled_vector(data, length, openmp, context));
    check_created(v.get(), "wrap_compiled_vector");
    return v;
  }
  Vector v(openmp ? N_VMake_OpenMP(length, data, omp_get_max_threads(), context)
                  : N_VMake_Serial(length, data, context));
  check_created(v.get(), openmp ? "N_VMake_OpenMP" : "N_VMake_Serial");
  return v;
}

// ---- errors ---------------------------------------------------------------------------------

void ErrorLog::handler(int error_code, const char* /*module*/, const char* /*function*/, char* message, void* log) {
  auto* self = static_cast<ErrorLog*>(log);
  if (self == nullptr) return;
  if (error_code >= 0) {  // CV_WARNING / ARK_WARNING: not a failure
    ++self->warnings_;
    return;
  }
  std::string text = message != nullptr ? message : "";
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';  // our error boundary prints exactly one line
  self->last_error_ = std::move(text);
}

void ErrorLog::clear() {
  last_error_.clear();
  warnings_ = 0;
}

std::string flag_name(FlagFamily family, int flag) {
  char* name = nullptr;
  switch (family) {
    case FlagFamily::cvode: name = CVodeGetReturnFlagName(flag); break;
    case FlagFamily::cvode_linear: name = CVodeGetLinReturnFlagName(flag); break;
    case FlagFamily::cvode_diag: name = CVDiagGetReturnFlagName(flag); break;
    case FlagFamily::arkode: name = ARKStepGetReturnFlagName(flag); break;
    case FlagFamily::arkode_linear: name = ARKStepGetLinReturnFlagName(flag); break;
    case FlagFamily::generic: break;
  }
  if (name == nullptr) return "flag " + std::to_string(flag);
  std::string result(name);
  std::free(name);  // SUNDIALS 6 mallocs the name and leaves freeing it to the caller
  return result;
}

void check_flag(int flag, const char* call, FlagFamily family, const ErrorLog* log, std::optional<double> time) {
  if (flag >= 0) return;
  abandon_level_if_stop_requested();  // problem_rhs failed the step to end the level (level_stop.hpp)
  std::string message = std::string(call) + " failed: " + flag_name(family, flag);
  if (time) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, " at t = %.6e s", *time);
    message += buffer;
  }
  if (log != nullptr && !log->last_error().empty()) message += " (" + log->last_error() + ")";
  throw SolverError(message);
}

void check_created(const void* created, const char* call) {
  if (created == nullptr) throw SolverError(std::string(call) + " failed: returned NULL");
}

bool advance_has_work(double dt, long steps, long particles) {
  check_step(dt, steps);
  return steps > 0 && particles > 0;
}

// ---- the right-hand side --------------------------------------------------------------------

int problem_rhs(double t, N_Vector y, N_Vector ydot, void* problem_rhs_data) {
  // An unrecoverable failure ends CVODE's or ARKODE's step at once; check_flag then abandons the level.
  if (level_stop_requested()) return -1;
  const auto& data = *static_cast<const ProblemRhsData*>(problem_rhs_data);
  const Problem& problem = *data.problem;
  const sunindextype n = data.members;
  const int fields = problem.field_count();
  double* state = N_VGetArrayPointer(y);
  double* rate = N_VGetArrayPointer(ydot);
  constexpr sunindextype kBlock = 64;
  const sunindextype blocks = (n + kBlock - 1) / kBlock;
  // A parallel region costs a fork and a barrier per RHS evaluation: worth it only for large
  // populations (and a descheduled thread stalls the barrier on a busy machine).
#pragma omp parallel if (n >= 8192)
  {
    std::vector<const double*> in(static_cast<std::size_t>(fields));
    std::vector<double*> out(static_cast<std::size_t>(fields));
#pragma omp for schedule(static)
    for (sunindextype b = 0; b < blocks; ++b) {
      const sunindextype first = b * kBlock;
      for (int f = 0; f < fields; ++f) {
        in[static_cast<std::size_t>(f)] = state + f * n + first;
        out[static_cast<std::size_t>(f)] = rate + f * n + first;
      }
      problem.rhs(t, first, static_cast<int>(std::min(kBlock, n - first)), in.data(), out.data());
    }
  }
  return 0;
}

}  // namespace dlpverify::sun
