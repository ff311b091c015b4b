// Members first … first + count − 1 of a problem, as a problem of their own: a solver that works
// on a block of the population (the CVODE reference does) hands the problem the members' own
// indices, so a problem with per-member parameters sees the right ones.
//
// Every capability of the whole problem is passed through, shifted to the block's members where
// it depends on them (tests/test_capabilities.cpp holds every wrapper to that).
#pragma once

#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/extended.hpp"
#include "dlpverify/member_coordinate.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/solution_features.hpp"
#include "dlpverify/splitting.hpp"
#include "dlpverify/exchange_description.hpp"
#include "dlpverify/initial_members.hpp"

namespace dlpverify {

class SubPopulation final : public Problem,
                            public ClosedForm,
                            public SolutionKinks,
                            public TimeScale,
                            public InertFields,
                            public FusedStepper,
                            public StaggeredBlocks,
                            public SweepContraction,
                            public LinearDecay,
                            public CaseReport,
                            public ExchangeDescription,
                            public TimeUnit,
                            public MemberNoun,
                            public InitialMembers,
                            public MemberCoordinate,
                            public ExtendedRhs {
 public:
  SubPopulation(const Problem& whole, Eigen::Index first, Eigen::Index count);

  std::string name() const override { return whole_.name(); }
  std::vector<Field> fields() const override { return whole_.fields(); }
  std::vector<Variable> variables() const override { return whole_.variables(); }
  State measured(State state, double tau, Eigen::Index first = 0) const override {
    return whole_.measured(std::move(state), tau, first_ + first);
  }
  Eigen::Index members() const override { return count_; }
  double initial_time() const override { return whole_.initial_time(); }
  // Built for the block's members alone where the whole problem can (InitialMembers), else sliced.
  State initial_state() const override { return initial_members(0, count_); }
  void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    whole_.rhs(t, first_ + first, count, y, dydt);
  }

  void extended_rhs(const Extended& t, Eigen::Index first, int count, const Extended* const* y,
                    Extended* const* dydt) const override {
    whole_.capability<ExtendedRhs>()->extended_rhs(t, first_ + first, count, y, dydt);
  }

  State solution(Eigen::Index first, const State& initial, double tau) const override {
    return whole_.capability<ClosedForm>()->solution(first_ + first, initial, tau);
  }
  std::string formula() const override { return whole_.capability<ClosedForm>()->formula(); }
  bool manufactured() const override { return whole_.capability<ClosedForm>()->manufactured(); }
  std::vector<double> kink_times(Eigen::Index first, const State& initial) const override {
    return whole_.capability<SolutionKinks>()->kink_times(first_ + first, initial);
  }
  double time_scale(Eigen::Index member, const double* y, double tau) const override {
    return whole_.capability<TimeScale>()->time_scale(first_ + member, y, tau);
  }
  std::vector<bool> inert_fields() const override { return whole_.capability<InertFields>()->inert_fields(); }
  FusedSteps fused_steps(const void* tableau, int block) const override {
    return whole_.capability<FusedStepper>()->fused_steps(tableau, block);
  }
  std::vector<FieldBlock> staggered_blocks() const override { return whole_.capability<StaggeredBlocks>()->staggered_blocks(); }
  double jacobi_radius(double dt) const override { return whole_.capability<SweepContraction>()->jacobi_radius(dt); }
  double gauss_seidel_radius(double dt) const override {
    return whole_.capability<SweepContraction>()->gauss_seidel_radius(dt);
  }
  std::string jacobi_radius_formula() const override { return whole_.capability<SweepContraction>()->jacobi_radius_formula(); }
  std::string gauss_seidel_radius_formula() const override {
    return whole_.capability<SweepContraction>()->gauss_seidel_radius_formula();
  }
  double step_limit() const override { return whole_.capability<SweepContraction>()->step_limit(); }
  std::string step_limit_formula() const override { return whole_.capability<SweepContraction>()->step_limit_formula(); }
  double radius_exponent() const override { return whole_.capability<SweepContraction>()->radius_exponent(); }
  void linear_decay(Eigen::Index first, int count, double* const* lambda) const override {
    whole_.capability<LinearDecay>()->linear_decay(first_ + first, count, lambda);
  }
  nlohmann::json parameters() const override { return whole_.capability<CaseReport>()->parameters(); }
  std::vector<MemberReduction> diagnostic_reductions() const override {
    return whole_.capability<CaseReport>()->diagnostic_reductions();
  }
  Eigen::ArrayXXd member_terms(Eigen::Index first, const State& initial, const State& finest,
                               double t_end) const override {
    return whole_.capability<CaseReport>()->member_terms(first_ + first, initial, finest, t_end);
  }
  // The whole's diagnostics: `reduced` is over every member of the whole population.
  nlohmann::json diagnostics(const std::vector<double>& reduced, double t_end) const override {
    return whole_.capability<CaseReport>()->diagnostics(reduced, t_end);
  }
  std::string time_unit() const override { return whole_.capability<TimeUnit>()->time_unit(); }
  MemberNouns member_nouns() const override { return whole_.capability<MemberNoun>()->member_nouns(); }
  State initial_members(Eigen::Index first, Eigen::Index count) const override {
    if (const auto* own = whole_.capability<InitialMembers>()) return own->initial_members(first_ + first, count);
    return whole_.initial_state().middleRows(first_ + first, count);
  }
  Eigen::ArrayXd member_coordinate(Eigen::Index first, Eigen::Index count) const override {
    return whole_.capability<MemberCoordinate>()->member_coordinate(first_ + first, count);
  }
  // The whole description with each member's data cut to the block.
  ProblemDescription description() const override;

 private:
  template <class C>
  void pass_through() {
    if (whole_.capability<C>()) provide<C>(*this);
  }

  const Problem& whole_;
  Eigen::Index first_, count_;
};

inline SubPopulation::SubPopulation(const Problem& whole, Eigen::Index first, Eigen::Index count)
    : whole_(whole), first_(first), count_(count) {
  pass_through<ClosedForm>();
  pass_through<SolutionKinks>();
  pass_through<TimeScale>();
  pass_through<InertFields>();
  pass_through<FusedStepper>();
  pass_through<StaggeredBlocks>();
  pass_through<SweepContraction>();
  pass_through<LinearDecay>();
  pass_through<CaseReport>();
  pass_through<MemberNoun>();
  pass_through<ExchangeDescription>();
  pass_through<TimeUnit>();
  pass_through<InitialMembers>();
  pass_through<MemberCoordinate>();
  pass_through<ExtendedRhs>();
}

inline ProblemDescription SubPopulation::description() const {
  ProblemDescription d = whole_.capability<ExchangeDescription>()->description();
  for (auto& [field, values] : d.member_data) values = values.segment(first_, count_).eval();
  return d;
}

}  // namespace dlpverify
