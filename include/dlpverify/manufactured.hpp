/// @file
/// A manufactured solution for any problem: the method of manufactured solutions applied to a
/// population of ODEs (docs/verification.md, "Manufactured solutions").
///
/// For a problem y′ = f(t, y) and a smooth, explicitly time-dependent trajectory ŷ(t) built from
/// the problem's own initial state, the manufactured problem is
/// @code{.unparsed}
///   y′ = f(t, y) + ŷ′(t) − f(t, ŷ(t)),   y(t0) = ŷ(t0) = y0,
/// @endcode
/// whose exact solution is ŷ: its closed form, whether or not the problem has one. ŷ′ is the
/// trajectory family's own derivative, never a finite difference. The source ŷ′(t) − f(t, ŷ(t))
/// depends on t explicitly, so a stage taken at the wrong time (a slipped node c_i of a
/// tableau) shows in the error, which no autonomous problem can show.
///
/// The trajectory of member p, field f, with τ = t − t0 and a per-member angular frequency
/// ω_p = (2π / duration)(1 + ½ frac(p φ)), φ the golden ratio's fraction:
/// @code{.unparsed}
///   y0 ≠ 0:  ŷ = y0 exp(A [sin(ω_p τ + θ_pf) − sin θ_pf])      (keeps the sign of y0)
///   y0 = 0:  ŷ = A s_f (1 − cos ω_p τ)                          (s_f: the field's scale)
///   f inert: ŷ = y0                                             (InertFields of the problem)
/// @endcode
/// with A = kManufacturedAmplitude and a phase θ_pf = 2π frac(p φ + f √2): a positive field (a
/// diameter, a mass, a temperature) stays positive, a sign never changes, and no member moves in
/// lockstep with another.
#pragma once

#include <memory>
#include <string>

#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/member_coordinate.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/solution_features.hpp"
#include "dlpverify/splitting.hpp"

namespace dlpverify {

/// The relative amplitude A of the manufactured trajectories.
inline constexpr double kManufacturedAmplitude = 0.1;

/// y′ = f(t, y) + ŷ′(t) − f(t, ŷ(t)) for a problem f, with the closed form ŷ (this file's description).
///
/// Capabilities: its own ClosedForm (ŷ) and CaseReport (the problem's parameters and the
/// trajectory's; no diagnostics, which describe the problem's own solution). Passed through:
/// InertFields (an inert field's trajectory is constant, so its source is zero), StaggeredBlocks,
/// LinearDecay (the source does not depend on y, so f = −λ∘y + g stays such a split), TimeScale,
/// TimeUnit, MemberNoun, MemberCoordinate (ŷ starts from the problem's members) and SweepContraction (the
/// source does not depend on y, so a sweep's iteration matrix is the problem's). Declined: FusedStepper (a fused stepper bypasses rhs, and so the source),
/// SolutionKinks (ŷ is smooth) and an exchange description (a program outside dlpverify evaluates
/// its own right-hand side, without the source).
class ManufacturedProblem final : public Problem,
                                  public ClosedForm,
                                  public CaseReport,
                                  public InertFields,
                                  public StaggeredBlocks,
                                  public SweepContraction,
                                  public LinearDecay,
                                  public TimeScale,
                                  public TimeUnit,
                                  public MemberNoun,
                                  public MemberCoordinate {
 public:
  /// The manufactured problem of `problem` over a study of `duration` after t0 (ω_p ≥ 2π/duration:
  /// every trajectory turns at least once). Throws InputError naming "duration" unless it is
  /// positive and finite, and "initial state" when a value is not finite. Holds a reference to
  /// `problem` and a copy of its initial state.
  ManufacturedProblem(const Problem& problem, double duration);
  /// The same, owning `problem`.
  ManufacturedProblem(std::unique_ptr<const Problem> problem, double duration);

  std::string name() const override { return problem_.name(); }  ///< the problem's
  std::vector<Field> fields() const override { return problem_.fields(); }  ///< the problem's
  std::vector<Variable> variables() const override { return problem_.variables(); }  ///< the problem's
  /// The problem's measured columns.
  State measured(State state, double tau, Eigen::Index first = 0) const override {
    return problem_.measured(std::move(state), tau, first);
  }
  Eigen::Index members() const override { return problem_.members(); }  ///< the problem's
  double initial_time() const override { return problem_.initial_time(); }  ///< the problem's
  State initial_state() const override { return initial_; }  ///< ŷ(t0) = y0, the problem's
  /// f(t, y) + ŷ′(t) − f(t, ŷ(t)) of the members first … first + count − 1.
  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override;

  /// ŷ(t0 + tau) of the members first … (from the problem's own initial state, which `initial` must be).
  State solution(Eigen::Index first, const State& initial, double tau) const override;
  std::string formula() const override;  ///< the construction, for reports
  bool manufactured() const override { return true; }  ///< ŷ is manufactured
  nlohmann::json parameters() const override;  ///< the problem's, and the trajectory's
  /// None: the problem's diagnostics describe its own solution.
  std::vector<MemberReduction> diagnostic_reductions() const override { return {}; }
  /// No quantity: a column-less row per member.
  Eigen::ArrayXXd member_terms(Eigen::Index, const State& initial, const State&, double) const override {
    return Eigen::ArrayXXd(initial.rows(), 0);
  }
  /// An empty object.
  nlohmann::json diagnostics(const std::vector<double>&, double) const override { return nlohmann::json::object(); }
  std::vector<bool> inert_fields() const override { return inert_; }  ///< the problem's
  std::vector<FieldBlock> staggered_blocks() const override { return dlpverify::staggered_blocks(problem_); }  ///< the problem's
  void linear_decay(Eigen::Index first, int count, double* const* lambda) const override;  ///< the problem's λ
  /// The problem's.
  double jacobi_radius(double dt) const override { return problem_.capability<SweepContraction>()->jacobi_radius(dt); }
  /// The problem's.
  double gauss_seidel_radius(double dt) const override {
    return problem_.capability<SweepContraction>()->gauss_seidel_radius(dt);
  }
  /// The problem's.
  std::string jacobi_radius_formula() const override {
    return problem_.capability<SweepContraction>()->jacobi_radius_formula();
  }
  /// The problem's.
  std::string gauss_seidel_radius_formula() const override {
    return problem_.capability<SweepContraction>()->gauss_seidel_radius_formula();
  }
  /// The problem's.
  double step_limit() const override { return problem_.capability<SweepContraction>()->step_limit(); }
  /// The problem's.
  std::string step_limit_formula() const override { return problem_.capability<SweepContraction>()->step_limit_formula(); }
  /// The problem's.
  double radius_exponent() const override { return problem_.capability<SweepContraction>()->radius_exponent(); }
  /// The problem's time scale, or 1/ω_p where the trajectory is faster.
  double time_scale(Eigen::Index member, const double* y, double tau) const override;
  std::string time_unit() const override;  ///< the problem's
  MemberNouns member_nouns() const override { return dlpverify::member_nouns(problem_); }  ///< the problem's
  /// The problem's.
  Eigen::ArrayXd member_coordinate(Eigen::Index first, Eigen::Index count) const override {
    return problem_.capability<MemberCoordinate>()->member_coordinate(first, count);
  }

  /// ŷ and ŷ′ of member p's field f at t0 + tau.
  void trajectory(Eigen::Index p, int f, double tau, double& value, double& rate) const;

 private:
  double omega(Eigen::Index p) const;

  std::unique_ptr<const Problem> owned_;  // when constructed owning the problem
  const Problem& problem_;
  double duration_;
  State initial_;
  std::vector<double> scale_;  // s_f: field_scales of the initial state
  std::vector<bool> inert_;
};

/// The manufactured problem of `problem` over `duration`, owning it (ManufacturedProblem).
std::unique_ptr<Problem> make_manufactured(std::unique_ptr<const Problem> problem, double duration);

}  // namespace dlpverify
