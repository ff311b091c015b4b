/// @file
/// The first exception thrown on any thread of an OpenMP parallel region, rethrown after it. An
/// exception may not leave a parallel region (the program would terminate, exit 134, instead of
/// failing with the exit code the exception means), so each iteration that calls code of the
/// problem's or the user's catches, and the region's caller rethrows:
/// @code{.unparsed}
///   FirstFailure failure;
///   #pragma omp parallel for
///   for (…) { try { problem.rhs(…); } catch (...) { failure.capture(); } }
///   failure.rethrow();
/// @endcode
/// Which exception is kept when several threads fail is the first to arrive, not a fixed one.
#pragma once

#include <exception>
#include <mutex>

namespace dlpverify {

/// The first exception captured by any thread, rethrown by rethrow().
class FirstFailure {
 public:
  /// Inside a catch block: keeps the exception being handled unless one is kept already.
  void capture() noexcept {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_) failure_ = std::current_exception();
  }
  /// After the region: rethrows the kept exception, if any.
  void rethrow() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr failure_;
};

}  // namespace dlpverify
