// The DLP particle cloud as a dlpverify Problem (docs/model.md §1–§2): the lattice cloud
// launched with the similarity solution, the right-hand side of its active terms, and the
// case's closed form where it has one. Fields x, y, z, vx, vy, vz, T, m; measured variables
// position and velocity, temperature with heat transfer, mass with burning.
#pragma once

#include <optional>

#include "dlpverify/extended.hpp"
#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/problem.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/solution_features.hpp"
#include "dlpverify/exchange_description.hpp"
#include "dlpverify/initial_members.hpp"
#include "problems/dlp/case.hpp"
#include "problems/dlp/cloud.hpp"
#include "problems/dlp/block_rates.hpp"
#include "problems/dlp/fused_steps.hpp"
#include "dlpverify/member_coordinate.hpp"
#include "problems/dlp/rates.hpp"

namespace dlpverify::dlp {

// Capabilities: the closed form (where the case has one), kinks and time scales, inert fields
// and fused steps for the Runge–Kutta integrators, parameters and diagnostics, the exchange
// description, a lattice cloud's members built alone (a rank's share under mpirun), and each
// particle's similarity coordinate ξ for the per-particle view.
class DlpProblem final : public Problem,
                         public ClosedForm,
                         public SolutionKinks,
                         public TimeScale,
                         public InertFields,
                         public FusedStepper,
                         public CaseReport,
                         public MemberNoun,
                         public ExchangeDescription,
                         public InitialMembers,
                         public MemberCoordinate,
                         public ExtendedRhs {
 public:
  // The study cloud of a case: the lattice launched at t0 = R_out Δ / u_s (docs/model.md §2).
  DlpProblem(const Case& test_case, const Parameters& parameters, const Lattice& lattice, const Launch& launch);
  // Any initial cloud at t0, and optionally another closed form in place of the case's (the
  // source paper's published formulas, audited beside the corrected ones).
  DlpProblem(const Case& test_case, const Parameters& parameters, Cloud initial, double t0,
             exact::ParticleSolution other_solution = nullptr, std::string solution_detail = {});

  std::string name() const override { return case_->name; }
  MemberNouns member_nouns() const override { return {"particle", "particles"}; }
  std::vector<Field> fields() const override;
  std::vector<Variable> variables() const override;
  Eigen::Index members() const override { return members_; }
  double initial_time() const override { return t0_; }
  // A lattice cloud is built afresh on each call (a few ms per million particles) rather than
  // held: the study's memory is then the reference and two levels (docs/verification.md, "Memory").
  State initial_state() const override;
  // The lattice's points first … first + count − 1 alone (make_cloud_members).
  State initial_members(Eigen::Index first, Eigen::Index count) const override;

  // The block in SIMD lanes (block_rates.hpp), or particle by particle on the scalar path.
  void rhs(double t, Eigen::Index /*first*/, int count, const double* const* y, double* const* dydt) const override {
    if (path_ != RhsPath::scalar) return block_rates_(count, y, dydt);
    for (int i = 0; i < count; ++i) rates_(t, BlockMember<const double*>{y, i}, BlockMember<double*>{dydt, i});
  }
  // The same formulas in Extended, particle by particle (every term: drag and its law, gravity,
  // heat, burning). The gas is steady: t is unused, as in rhs.
  void extended_rhs(const Extended& /*t*/, Eigen::Index /*first*/, int count, const Extended* const* y,
                    Extended* const* dydt) const override {
    for (int i = 0; i < count; ++i) rates_(0.0, BlockMember<const Extended*>{y, i}, BlockMember<Extended*>{dydt, i});
  }
  // The rates inlined into the built-in tableaux' stage loops where the terms allow (fused_steps.hpp).
  FusedSteps fused_steps(const void* tableau, int block) const override {
    if (path_ != RhsPath::simd) return {};
    return dlp_fused_steps(block_rates_.constants(), tableau, block);
  }
  // simd: fused steps where they exist, else the block kernels. simd_unfused: the block kernels
  // only. scalar: libm, one particle at a time. The last two are kept to compare with:
  // `dlpverify bench` and the tests of the SIMD paths.
  enum class RhsPath { simd, simd_unfused, scalar };
  void set_rhs_path(RhsPath path) { path_ = path; }

  State solution(Eigen::Index first, const State& initial, double tau) const override;
  std::string formula() const override { return solution_detail_; }

  std::vector<double> kink_times(Eigen::Index first, const State& initial) const override;
  double time_scale(Eigen::Index member, const double* y, double tau) const override;

  // T without heat transfer, m without burning.
  std::vector<bool> inert_fields() const override {
    std::vector<bool> inert(kFields, false);
    inert[TEMPERATURE] = !physics_.terms.heat;
    inert[MASS] = !physics_.terms.burning;
    return inert;
  }

  nlohmann::json parameters() const override;
  ProblemDescription description() const override;
  std::vector<MemberReduction> diagnostic_reductions() const override;
  Eigen::ArrayXXd member_terms(Eigen::Index first, const State& initial, const State& finest, double t_end) const override;
  nlohmann::json diagnostics(const std::vector<double>& reduced, double t_end) const override;

  // The capabilities this problem has (the closed form only where the case has one).
  void provide_capabilities();

  const Physics& physics() const { return physics_; }
  const Case& test_case() const { return *case_; }
  // ξ = ‖x0‖ / r_s0 of each particle at launch (docs/model.md §2): where in the cloud an error lives.
  Eigen::ArrayXd member_coordinate(Eigen::Index first, Eigen::Index count) const override;

 private:
  const Case* case_;
  Physics physics_;
  ParticleRates rates_;
  BlockRates block_rates_;
  RhsPath path_ = RhsPath::simd;
  Cloud initial_;                  // a cloud given as it is; empty for a lattice cloud
  std::optional<Lattice> lattice_;  // the lattice cloud's recipe
  Eigen::Index members_ = 0;
  double t0_;
  Launch launch_;
  exact::ParticleSolution solution_;
  std::string solution_detail_;
};

}  // namespace dlpverify::dlp
