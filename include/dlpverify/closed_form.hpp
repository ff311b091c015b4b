/// @file
/// The closed form of a problem, where it has one: the exact reference of a study and of the
/// audit. A capability (problem.hpp): a problem without one is studied against a computed reference.
#pragma once

#include <string>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// A problem's exact solution y(t0 + tau) from its state at t0.
class ClosedForm : public Capability {
 public:
  /// The state at t0 + tau of members first … first + initial.rows() − 1 whose state at t0 is `initial`.
  virtual State solution(Eigen::Index first, const State& initial, double tau) const = 0;
  /// Where the closed form comes from: its formula, or the section of the docs that derives it.
  virtual std::string formula() const = 0;
  /// Whether this closed form is a manufactured trajectory ŷ (dlpverify/manufactured.hpp): a
  /// study with a manufactured reference takes such a problem as it is and wraps any other.
  virtual bool manufactured() const { return false; }
};

/// Whether `problem` provides a ClosedForm.
bool has_closed_form(const Problem& problem);
/// Whether `problem`'s closed form is a manufactured trajectory (ClosedForm::manufactured).
bool is_manufactured(const Problem& problem);
/// The whole population's state at t0 + tau from `initial` (N × F); throws InputError naming the
/// exact reference when the problem has no closed form.
State closed_form(const Problem& problem, const State& initial, double tau);
/// The closed form's formula, or "no closed form".
std::string reference_detail(const Problem& problem);

}  // namespace dlpverify
