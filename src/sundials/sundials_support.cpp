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
#include "problems/dlp/particle.hpp"

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
  Vector v(openmp ? N_VNew_OpenMP(length, omp_get_max_threads(), context) : N_VNew_Serial(length, context));
  check_created(v.get(), openmp ? "N_VNew_OpenMP" : "N_VNew_Serial");
  if (compiled) use_compiled_operations(v.get(), openmp);
  return v;
}

Vector wrap_vector(double* data, sunindextype length, bool openmp, SUNContext context, bool compiled) {
  Vector v(openmp ? N_VMake_OpenMP(length, data, omp_get_max_threads(), context)
                  : N_VMake_Serial(length, data, context));
  check_created(v.get(), openmp ? "N_VMake_OpenMP" : "N_VMake_Serial");
  if (compiled) use_compiled_operations(v.get(), openmp);
  return v;
}

// ---- compiled vector operations -------------------------------------------------------------
//
// Each loop is element-wise (z may alias x or y) and mirrors the serial N_Vector of SUNDIALS 6.4.1
// (src/nvector/serial/nvector_serial.c). Threaded<true> splits loops over the OpenMP threads once
// the vector is long enough for that to pay.

namespace {

constexpr sunindextype kThreadedLength = 4096;

template <bool Threaded>
struct Ops {
  static bool threaded(sunindextype n) { return Threaded && n >= kThreadedLength; }

  static void linear_sum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    const double* yd = N_VGetArrayPointer(y);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
  }
  static void constant(double c, N_Vector z) {
    const sunindextype n = N_VGetLength(z);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = c;
  }
  static void product(N_Vector x, N_Vector y, N_Vector z) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    const double* yd = N_VGetArrayPointer(y);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] * yd[i];
  }
  static void divide(N_Vector x, N_Vector y, N_Vector z) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    const double* yd = N_VGetArrayPointer(y);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] / yd[i];
  }
  static void scale(double c, N_Vector x, N_Vector z) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = c * xd[i];
  }
  static void absolute(N_Vector x, N_Vector z) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = std::fabs(xd[i]);
  }
  static void inverse(N_Vector x, N_Vector z) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = 1.0 / xd[i];
  }
  static void add_constant(N_Vector x, double b, N_Vector z) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] + b;
  }
  static void compare(double c, N_Vector x, N_Vector z) {  // z = (|x| ≥ c) ? 1 : 0
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double* zd = N_VGetArrayPointer(z);
#pragma omp parallel for simd schedule(static) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) zd[i] = std::fabs(xd[i]) >= c ? 1.0 : 0.0;
  }
  static sunbooleantype invert_test(N_Vector x, N_Vector z) {  // z = 1/x where x ≠ 0; false if any x = 0
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double* zd = N_VGetArrayPointer(z);
    int zeros = 0;
#pragma omp parallel for schedule(static) reduction(+ : zeros) if (threaded(n))
    for (sunindextype i = 0; i < n; ++i) {
      if (xd[i] == 0.0)
        ++zeros;
      else
        zd[i] = 1.0 / xd[i];
    }
    return zeros == 0 ? SUNTRUE : SUNFALSE;
  }

  static double dot_product(N_Vector x, N_Vector y) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    const double* yd = N_VGetArrayPointer(y);
    double sum = 0.0;
#pragma omp parallel for simd schedule(static) reduction(+ : sum) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) sum += xd[i] * yd[i];
    return sum;
  }
  static double max_norm(N_Vector x) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double largest = 0.0;
#pragma omp parallel for simd schedule(static) reduction(max : largest) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) largest = std::max(largest, std::fabs(xd[i]));
    return largest;
  }
  static double minimum(N_Vector x) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double smallest = n > 0 ? xd[0] : SUN_BIG_REAL;
#pragma omp parallel for simd schedule(static) reduction(min : smallest) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) smallest = std::min(smallest, xd[i]);
    return smallest;
  }
  static double l1_norm(N_Vector x) {
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    double sum = 0.0;
#pragma omp parallel for simd schedule(static) reduction(+ : sum) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) sum += std::fabs(xd[i]);
    return sum;
  }
  static double weighted_square_sum(N_Vector x, N_Vector w) {  // Σ (x w)²
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    const double* wd = N_VGetArrayPointer(w);
    double sum = 0.0;
#pragma omp parallel for simd schedule(static) reduction(+ : sum) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) {
      const double product = xd[i] * wd[i];
      sum += product * product;
    }
    return sum;
  }
  static double weighted_square_sum_masked(N_Vector x, N_Vector w, N_Vector id) {  // over id > 0
    const sunindextype n = N_VGetLength(x);
    const double* xd = N_VGetArrayPointer(x);
    const double* wd = N_VGetArrayPointer(w);
    const double* idd = N_VGetArrayPointer(id);
    double sum = 0.0;
#pragma omp parallel for simd schedule(static) reduction(+ : sum) if (parallel: threaded(n))
    for (sunindextype i = 0; i < n; ++i) {
      const double product = idd[i] > 0.0 ? xd[i] * wd[i] : 0.0;
      sum += product * product;
    }
    return sum;
  }
  static double wrms_norm(N_Vector x, N_Vector w) {
    return std::sqrt(weighted_square_sum(x, w) / static_cast<double>(N_VGetLength(x)));
  }
  static double wrms_norm_masked(N_Vector x, N_Vector w, N_Vector id) {
    return std::sqrt(weighted_square_sum_masked(x, w, id) / static_cast<double>(N_VGetLength(x)));
  }
  static double wl2_norm(N_Vector x, N_Vector w) { return std::sqrt(weighted_square_sum(x, w)); }

  // z = Σ_j c_j X_j (z may be one of the X_j: each entry reads all X_j before writing z).
  static int linear_combination(int count, double* c, N_Vector* xs, N_Vector z) {
    if (count < 1) return -1;  // SUNDIALS: SUN_ERR_ARG_OUTOFRANGE / -1
    const sunindextype n = N_VGetLength(z);
    double* zd = N_VGetArrayPointer(z);
    constexpr int kBlock = 16;  // columns summed per pass
    for (int first = 0; first < count; first += kBlock) {
      const int last = std::min(count, first + kBlock);
      const double* columns[kBlock];
      for (int j = first; j < last; ++j) columns[j - first] = N_VGetArrayPointer(xs[j]);
      const bool accumulate = first > 0;
#pragma omp parallel for schedule(static) if (threaded(n))
      for (sunindextype i = 0; i < n; ++i) {
        double sum = accumulate ? zd[i] : 0.0;
        for (int j = first; j < last; ++j) sum += c[j] * columns[j - first][i];
        zd[i] = sum;
      }
    }
    return 0;
  }
  // Z_j = a_j x + Y_j for j < count.
  static int scale_add_multi(int count, double* a, N_Vector x, N_Vector* ys, N_Vector* zs) {
    if (count < 1) return -1;
    for (int j = 0; j < count; ++j) linear_sum(a[j], x, 1.0, ys[j], zs[j]);
    return 0;
  }

  static void install(N_Vector v) {
    N_Vector_Ops ops = v->ops;
    ops->nvlinearsum = linear_sum;
    ops->nvconst = constant;
    ops->nvprod = product;
    ops->nvdiv = divide;
    ops->nvscale = scale;
    ops->nvabs = absolute;
    ops->nvinv = inverse;
    ops->nvaddconst = add_constant;
    ops->nvdotprod = dot_product;
    ops->nvmaxnorm = max_norm;
    ops->nvwrmsnorm = wrms_norm;
    ops->nvwrmsnormmask = wrms_norm_masked;
    ops->nvmin = minimum;
    ops->nvwl2norm = wl2_norm;
    ops->nvl1norm = l1_norm;
    ops->nvcompare = compare;
    ops->nvinvtest = invert_test;
    ops->nvlinearcombination = linear_combination;
    ops->nvscaleaddmulti = scale_add_multi;
    // The local reductions (the same, for a vector on one process).
    ops->nvdotprodlocal = dot_product;
    ops->nvmaxnormlocal = max_norm;
    ops->nvminlocal = minimum;
    ops->nvl1normlocal = l1_norm;
    ops->nvinvtestlocal = invert_test;
    ops->nvwsqrsumlocal = weighted_square_sum;
    ops->nvwsqrsummasklocal = weighted_square_sum_masked;
  }
};

}  // namespace

void use_compiled_operations(N_Vector v, bool threaded) {
  const N_Vector_ID id = N_VGetVectorID(v);
  if (id != SUNDIALS_NVEC_SERIAL && id != SUNDIALS_NVEC_OPENMP)
    throw SolverError("use_compiled_operations failed: not a serial or OpenMP N_Vector");
  if (threaded)
    Ops<true>::install(v);
  else
    Ops<false>::install(v);
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
    case FlagFamily::generic: break;
  }
  if (name == nullptr) return "flag " + std::to_string(flag);
  std::string result(name);
  std::free(name);  // SUNDIALS 6 mallocs the name and leaves freeing it to the caller
  return result;
}

void check_flag(int flag, const char* call, FlagFamily family, const ErrorLog* log, std::optional<double> time) {
  if (flag >= 0) return;
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
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("time step", std::to_string(dt), "must be positive and finite");
  if (steps < 0) throw InputError("steps", std::to_string(steps), "must be non-negative");
  return steps > 0 && particles > 0;
}

// ---- the right-hand side --------------------------------------------------------------------

int problem_rhs(double t, N_Vector y, N_Vector ydot, void* problem_rhs_data) {
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
