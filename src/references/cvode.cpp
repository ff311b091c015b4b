// The CVODE reference: Adams at a tight relative tolerance, its error estimated by a second solve
// at rtol/10. Members are independent, so the population is solved in blocks of kReferenceBlock
// members, one CVODE per thread (dlpverify/reference.hpp gives the reason).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "dlpverify/first_failure.hpp"
#include "dlpverify/norms.hpp"
#include "dlpverify/solution_features.hpp"
#include "harness/distribution.hpp"
#include "harness/sub_population.hpp"
#include "integrators/sundials/cvode_integrator.hpp"
#include "io/progress.hpp"
#include "references/source.hpp"

namespace dlpverify {

namespace {

constexpr Eigen::Index kReferenceBlock = 1024;

// One block from τ = tau_from to tau_from + duration, restarting at the block's kinks if asked.
void solve_block(CvodeIntegrator& cvode, const Problem& problem, State& block, const std::vector<double>& kinks,
                 double t0, double tau_from, double duration) {
  std::vector<double> stops;
  for (double kink : kinks)
    if (std::isfinite(kink) && kink > tau_from && kink < tau_from + duration) stops.push_back(kink);
  std::sort(stops.begin(), stops.end());
  stops.push_back(tau_from + duration);
  double reached = tau_from;
  for (double stop : stops) {
    if (stop <= reached) continue;
    cvode.advance(problem, block, t0 + reached, stop - reached, 1);  // no step longer than the segment
    reached = stop;
  }
}

// solve_with_cvode, its blocks counted on the progress line as `what` ("reference block", …).
State solve_in_blocks(const Problem& problem, const State& from, double tau_from, double duration,
                      const ReferenceSettings& settings, nlohmann::json& statistics, const State* scale_from,
                      const char* what) {
  CvodeSettings cvode;
  cvode.rtol = settings.rtol;
  cvode.atol = absolute_tolerances(problem, scale_from ? *scale_from : from, settings.rtol);
  cvode.method = CvodeMethod::adams;  // non-stiff problems; its step sequence is also the most reproducible
  cvode.max_steps = settings.max_steps;
  // Adams orders above 7 cost more than they save here: on `full` at rtol 1e-13 (the error
  // estimate's solve) CVODE took 15 % more steps with order 8 allowed than with 7, and each step's
  // Nordsieck update costs ~q²/2 vector sums. At rtol 1e-12 no block went above order 7.
  cvode.max_order = 7;
  cvode.openmp_vector = false;  // the threads share out blocks instead
  const double t0 = problem.initial_time();

  const Eigen::Index members = from.rows();
  const Eigen::Index blocks = (members + kReferenceBlock - 1) / kReferenceBlock;
  std::vector<double> kinks(static_cast<std::size_t>(members), std::nan(""));
  if (settings.restart_at_kinks) kinks = kink_times(problem, from);
  State result(members, from.cols());
  long steps_max = 0;
  SolverStatistics total;  // the blocks' counts added
  FirstFailure failure;
  progress::Task task(what, static_cast<long>(blocks));
#pragma omp parallel
  {
    CvodeIntegrator integrator(cvode);
    State block;
#pragma omp for schedule(dynamic)
    for (Eigen::Index b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * kReferenceBlock;
      const Eigen::Index count = std::min(kReferenceBlock, members - first);
      block = from.middleRows(first, count);
      const std::vector<double> block_kinks(kinks.begin() + first, kinks.begin() + first + count);
      try {
        const SubPopulation part(problem, first, count);
        solve_block(integrator, part, block, block_kinks, t0, tau_from, duration);
      } catch (...) {
        failure.capture();
        continue;
      }
      result.middleRows(first, count) = block;
      const SolverStatistics counts = integrator.statistics();
#pragma omp critical(dlpverify_reference_statistics)
      {
        steps_max = std::max(steps_max, counts.steps.value_or(0));
        total += counts;
      }
      task.advance();
    }
  }
  failure.rethrow();
  // Under MPI the counts are every process's (harness/distribution.hpp); serially these are the identity.
  const Distribution& all = distribution();
  statistics = {{"method", "adams"},          {"rtol", settings.rtol},          {"max_order", cvode.max_order},
                {"blocks", all.sum(static_cast<long>(blocks))}, {"particles_per_block", kReferenceBlock},
                {"steps_max", all.max(steps_max)},     {"steps_total", all.sum(total.steps.value_or(0))},
                {"rhs_evals_total", all.sum(total.rhs_evals.value_or(0))}};
  return result;
}

class CvodeReference final : public references::ReferenceSource {
 public:
  explicit CvodeReference(const ReferenceSettings& settings) : settings_(settings) {}

  Reference compute(const Problem& problem, const State& initial, double t_end,
                    const std::vector<Variable>& variables) const override {
    const auto start = std::chrono::steady_clock::now();
    Reference reference;
    nlohmann::json first, second;
    reference.state = solve_in_blocks(problem, initial, 0.0, t_end, settings_, first, nullptr, "reference block");
    const double first_seconds = references::seconds_since(start);
    ReferenceSettings tighter_settings = settings_;
    tighter_settings.rtol = settings_.rtol / 10.0;
    const State tighter = solve_in_blocks(problem, initial, 0.0, t_end, tighter_settings, second, nullptr,
                                          "reference error estimate (rtol/10) block");
    const State measured = problem.measured(reference.state, t_end), measured_tighter = problem.measured(tighter, t_end);
    for (const Variable& v : variables) reference.error_estimate.push_back(error_norms(measured, measured_tighter, v).l2);

    char detail[160];
    std::snprintf(detail, sizeof detail,
                  "CVODE Adams, rtol %.0e, atol rtol x field scale; error estimated against rtol %.0e", settings_.rtol,
                  settings_.rtol / 10.0);
    reference.kind = reference_kind_name(ReferenceKind::cvode);
    reference.detail = detail;
    reference.statistics = {{"rtol", settings_.rtol},
                            {"wall_s", first_seconds},
                            {"solve", first},
                            {"error_estimate_solve", second},
                            {"error_estimate_wall_s", references::seconds_since(start) - first_seconds}};
    return reference;
  }

  // CVODE continued from the previous time.
  std::function<State(double tau)> trajectory(const Problem& problem, const State& initial) const override {
    return references::continued_trajectory(initial, [&problem, settings = settings_](State& state, double from, double to) {
      nlohmann::json ignored;
      state = solve_in_blocks(problem, state, from, to - from, settings, ignored, nullptr, "reference history block");
    });
  }

  // rtol/100, down to kTightestReferenceRtol.
  std::optional<ReferenceSettings> tightened(double /*ratio*/) const override {
    if (settings_.rtol <= kTightestReferenceRtol) return std::nullopt;
    ReferenceSettings tighter = settings_;
    tighter.rtol = std::max(settings_.rtol / 100.0, kTightestReferenceRtol);
    return tighter;
  }

 private:
  ReferenceSettings settings_;
};

}  // namespace

State solve_with_cvode(const Problem& problem, const State& from, double tau_from, double duration,
                       const ReferenceSettings& settings, nlohmann::json& statistics, const State* scale_from) {
  return solve_in_blocks(problem, from, tau_from, duration, settings, statistics, scale_from, "CVODE block");
}

std::unique_ptr<references::ReferenceSource> references::cvode_source(const ReferenceSettings& settings) {
  return std::make_unique<CvodeReference>(settings);
}

}  // namespace dlpverify
