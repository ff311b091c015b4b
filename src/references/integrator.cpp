// The integrator reference: any integrator at a fixed step Δt, its error estimated against a
// second solve at Δt/2 by Richardson's rule. With y_dt − y = C dt^p and y_{dt/2} − y = C (dt/2)^p,
// ‖y_dt − y‖ = ‖y_dt − y_{dt/2}‖ · 2^p / (2^p − 1). An integrator of unknown order (p = 0) gets
// twice the difference, the factor of p = 1, the largest of every p ≥ 1.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "dlpverify/errors.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/norms.hpp"
#include "io/format.hpp"
#include "references/source.hpp"

namespace dlpverify {

namespace {

void require_integrator(const ReferenceSettings& settings) {
  if (!settings.integrator) throw InputError("reference", "integrator", "no integrator given");
  if (!std::isfinite(settings.dt) || settings.dt <= 0.0)
    throw InputError("reference", "integrator", "its step dt = " + value_text(settings.dt) + " must be positive and finite");
}

// t_end / dt whole by the rule of level_steps (1e-9 relative), or InputError naming the reference.
long reference_steps(double t_end, double dt) {
  StudyPlan one_level;
  one_level.t_end = t_end;
  one_level.coarsest_dt = dt;
  one_level.levels = 1;
  try {
    return level_steps(one_level).front();
  } catch (const InputError& e) {
    throw InputError("reference", "integrator at dt = " + value_text(dt), e.reason());
  }
}

std::string detail_of(const Integrator& integrator, double dt) {
  const int order = integrator.order();
  char detail[320];
  if (order > 0)
    std::snprintf(detail, sizeof detail, "%s at dt = %s, error estimated against dt/2: the difference x 2^%d/(2^%d - 1)",
                  integrator.name().c_str(), value_text(dt).c_str(), order, order);
  else
    std::snprintf(detail, sizeof detail, "%s at dt = %s, error estimated against dt/2: its order is unknown, the difference x 2",
                  integrator.name().c_str(), value_text(dt).c_str());
  return detail;
}

class IntegratorReference final : public references::ReferenceSource {
 public:
  explicit IntegratorReference(const ReferenceSettings& settings) : settings_(settings) {}

  Reference compute(const Problem& problem, const State& initial, double t_end,
                    const std::vector<Variable>& variables) const override {
    require_integrator(settings_);
    Integrator& integrator = *settings_.integrator;
    const long steps = reference_steps(t_end, settings_.dt);
    const double t0 = problem.initial_time();
    const auto start = std::chrono::steady_clock::now();
    Reference reference;
    reference.state = initial;
    integrator.advance(problem, reference.state, t0, t_end / static_cast<double>(steps), steps);
    const SolverStatistics first = integrator.statistics();
    const double first_seconds = references::seconds_since(start);
    State halved = initial;
    integrator.advance(problem, halved, t0, t_end / static_cast<double>(2 * steps), 2 * steps);
    const SolverStatistics second = integrator.statistics();

    const int order = integrator.order();
    const State measured = problem.measured(reference.state, t_end), measured_halved = problem.measured(halved, t_end);
    reference.error_estimate = halved_step_error(measured, measured_halved, variables, order);
    reference.kind = reference_kind_name(ReferenceKind::integrator);
    reference.detail = detail_of(integrator, settings_.dt);
    reference.statistics = {{"integrator", integrator.name()},
                            {"order", order},
                            {"dt", settings_.dt},
                            {"steps", steps},
                            {"error_estimate_factor", halved_step_error_factor(order)},
                            {"wall_s", first_seconds},
                            {"solve", first},
                            {"error_estimate_solve", second},
                            {"error_estimate_wall_s", references::seconds_since(start) - first_seconds}};
    return reference;
  }

  // The integrator continued from the previous time: Δτ in ⌈Δτ/dt⌉ equal steps, since output
  // times need not be multiples of dt, and no step is longer.
  std::function<State(double tau)> trajectory(const Problem& problem, const State& initial) const override {
    require_integrator(settings_);
    return references::continued_trajectory(initial, [&problem, settings = settings_](State& state, double from, double to) {
      const double span = to - from;
      const long steps = std::max(1L, static_cast<long>(std::ceil(span / settings.dt * (1.0 - 1e-12))));
      settings.integrator->advance(problem, state, problem.initial_time() + from, span / static_cast<double>(steps), steps);
    });
  }

  // Δt/ratio, when the ratio is whole (t_end/Δt stays whole).
  std::optional<ReferenceSettings> tightened(double ratio) const override {
    if (ratio < 2.0 || ratio != std::round(ratio)) return std::nullopt;
    ReferenceSettings tighter = settings_;
    tighter.dt = settings_.dt / ratio;
    return tighter;
  }

 private:
  ReferenceSettings settings_;
};

}  // namespace

double halved_step_error_factor(int order) {
  return order > 0 ? std::ldexp(1.0, order) / (std::ldexp(1.0, order) - 1.0) : 2.0;
}

std::vector<double> halved_step_error(const State& solution, const State& halved, const std::vector<Variable>& variables,
                                      int order) {
  std::vector<double> error;
  for (const Variable& v : variables) error.push_back(halved_step_error_factor(order) * error_norms(solution, halved, v).l2);
  return error;
}

std::unique_ptr<references::ReferenceSource> references::integrator_source(const ReferenceSettings& settings) {
  return std::make_unique<IntegratorReference>(settings);
}

}  // namespace dlpverify
