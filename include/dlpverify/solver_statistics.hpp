/// @file
/// What an integrator counted in its last advance(), as typed members.
///
/// A count an integrator does not keep is std::nullopt, never 0: a fixed-step Runge–Kutta method
/// has no rejected steps to report, which is not the same as reporting none. The JSON form (the
/// reports' "solver_statistics" object) writes each reported count under the key the reports
/// have always used, e.g. {"steps": 80, "rhs_evals": 320}, and the extras beside them.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

namespace dlpverify {

/// An integrator's own figure beyond the common counts: absent (JSON null), a count, a real or a word.
using StatisticValue = std::variant<std::monostate, long, double, std::string>;

/// Solver statistics of one advance(); std::nullopt marks a count the integrator does not report.
struct SolverStatistics {
  /// Steps taken ("steps"); for a fixed step, the steps asked.
  std::optional<long> steps;
  /// Whole-population right-hand-side evaluations ("rhs_evals"): one per stage of a Runge–Kutta
  /// step, CVODE's nfe; comparable across integrators.
  std::optional<long> rhs_evals;
  /// Right-hand-side evaluations spent on Jacobian approximations ("rhs_evals_jacobian"; CVODE BDF).
  std::optional<long> rhs_evals_jacobian;
  /// Rejected steps: local error-test failures ("error_test_failures"; CVODE's netf).
  std::optional<long> error_test_failures;
  /// Nonlinear solver iterations ("nonlinear_iterations"; CVODE's nni).
  std::optional<long> nonlinear_iterations;
  /// Nonlinear solver convergence failures ("nonlinear_convergence_failures"; CVODE's nncf).
  std::optional<long> nonlinear_convergence_failures;
  /// Linear solver setups, i.e. Jacobian (re)evaluations and factorisations ("linear_solver_setups"; CVODE's nsetups).
  std::optional<long> linear_solver_setups;
  /// Iterations of an iterative linear solver ("linear_iterations"; CVODE with a Krylov solver).
  std::optional<long> linear_iterations;
  /// Integrator-specific figures by their report key, e.g. "method", "rtol", "command_seconds".
  /// A key never repeats one of the typed counts above.
  std::map<std::string, StatisticValue> extras;

  /// True when nothing was reported (an integrator that counts nothing; written as no object at all).
  bool empty() const;
  /// The extra `key` as a count, std::nullopt when absent or not a count.
  std::optional<long> extra_count(const std::string& key) const;
  /// The extra `key` as a real (a count converts), std::nullopt when absent or neither.
  std::optional<double> extra_real(const std::string& key) const;

  /// Adds `other`'s counts to these, member by member: a count reported by either side is the sum
  /// of the reported values; a count neither reports stays unreported. Extras describe one solve
  /// and are not added (these keep theirs). For blocks of one population solved apart.
  SolverStatistics& operator+=(const SolverStatistics& other);

  /// Member-wise equality, extras included (a real compared by value).
  friend bool operator==(const SolverStatistics&, const SolverStatistics&) = default;
};

/// Writes the reported counts under their keys, then the extras; an unreported count writes no key.
void to_json(nlohmann::json& j, const SolverStatistics& statistics);
/// Reads the object to_json writes: the typed keys must hold integers (std::invalid_argument
/// otherwise); every other key becomes an extra (a number, a string or null; anything else is
/// std::invalid_argument).
void from_json(const nlohmann::json& j, SolverStatistics& statistics);

}  // namespace dlpverify
