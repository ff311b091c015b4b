// CVODE (SUNDIALS) behind the Integrator interface: the high-accuracy reference of SPEC §3.
//
// The whole cloud is one N_Vector of length 8N that wraps the Cloud's column-major N × 8 buffer
// (field f of particle p at f·N + p) without copying; CVODE writes its answer straight back.
//   Adams (non-stiff): variable order 1–12, fixed-point nonlinear iteration, no Jacobian.
//   BDF (stiff):       variable order 1–5, Newton with a diagonal approximate Jacobian (CVDiag)
//                      or matrix-free GMRES (SPGMR). Never a dense 8N × 8N matrix.
// advance() integrates t0 → t0 + steps·dt with dt as the largest step and a stop time at the end,
// so the result lands on the final time exactly. name() "cvode", order() 0 (variable order).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "integrators/integrator.hpp"

namespace dlpverify {

// One value per field of a particle state (x, y, z, vx, vy, vz, T, m).
using FieldValues = std::array<double, kFields>;

enum class CvodeMethod { adams, bdf };
enum class CvodeLinearSolver { diagonal, spgmr };  // BDF's Newton iteration only

struct CvodeSettings {
  double rtol = 1e-10;
  // Absolute tolerance per field; when empty, absolute_tolerances(initial cloud, rtol).
  std::optional<FieldValues> atol;
  CvodeMethod method = CvodeMethod::adams;
  CvodeLinearSolver linear_solver = CvodeLinearSolver::diagonal;
  long max_steps = 100000;     // CVodeSetMaxNumSteps, per advance()
  bool openmp_vector = false;  // N_VNew_OpenMP with omp_get_max_threads(), else serial
  // Vector arithmetic compiled here instead of Debian's unoptimised SUNDIALS loops (4–5× faster
  // overall; see sun::use_compiled_operations). Off only to compare against SUNDIALS' own.
  bool compiled_vector_operations = true;
};

// The size of each field in a cloud: position and velocity by group (the largest |x|, |y|, |z|
// of any particle — the cloud radius for a lattice sphere — and likewise for velocity), T and m
// by their largest magnitude. A field that is zero everywhere (a cloud at rest) gets 1 (SI unit),
// so no absolute tolerance is ever zero.
FieldValues field_scales(const Cloud& cloud);

// rtol × field_scales(initial): positions, velocities, T and m have very different magnitudes
// (1e-4 m, 100 m/s, 1500 K, 1e-9 kg), so one scalar atol would be meaningless for some of them.
FieldValues absolute_tolerances(const Cloud& initial, double rtol);

class CvodeIntegrator final : public Integrator {
 public:
  explicit CvodeIntegrator(CvodeSettings settings = {});
  ~CvodeIntegrator() override;
  CvodeIntegrator(CvodeIntegrator&&) noexcept;
  CvodeIntegrator& operator=(CvodeIntegrator&&) noexcept;

  std::string name() const override { return "cvode"; }
  int order() const override { return 0; }
  // Throws SolverError (with CVODE's flag name, e.g. CV_TOO_MUCH_WORK) when CVODE gives up.
  void advance(const ParticleRates& rates, Cloud& cloud, double t0, double dt, long steps) override;
  // Of the last advance(): steps, rhs_evals, error_test_failures, nonlinear_iterations,
  // nonlinear_convergence_failures, last_order, last_step, current_time, …
  nlohmann::json statistics() const override;

  const CvodeSettings& settings() const { return settings_; }

 private:
  struct Solver;  // the SUNDIALS objects, kept across advance() calls of the same cloud size
  CvodeSettings settings_;
  std::unique_ptr<Solver> solver_;
  nlohmann::json statistics_ = nlohmann::json::object();
};

}  // namespace dlpverify
