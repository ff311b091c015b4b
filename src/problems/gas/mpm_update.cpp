#include "problems/gas/mpm_update.hpp"

#include "dlpverify/errors.hpp"
#include "problems/gas/problem.hpp"

namespace dlpverify::gas {

namespace {

using Step = double (*)(const Material&, double J_n, double T_n, double J_next);

// The orders are the ones worked out in material.cpp ("Order of NairnMPM's update, and the fix").
class TemperatureUpdate final : public Integrator {
 public:
  TemperatureUpdate(std::string name, int order, Step step) : name_(std::move(name)), order_(order), step_(step) {}
  std::string name() const override { return name_; }
  int order() const override { return order_; }

  // Parcel p moves through J_p(t0 + n dt), n = 0 … steps; T follows by the update.
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override {
    check_step(dt, steps);
    const auto* gas = dynamic_cast<const GasProblem*>(&problem);
    if (gas == nullptr)
      throw InputError("integrator", name_, "updates gas parcels along their paths; use it with the adiabat cases");
    check_shape(problem, state, "state");
    const double start = t0 - gas->initial_time();
#pragma omp parallel for schedule(static)
    for (Eigen::Index p = 0; p < state.rows(); ++p) {
      const CompressionPath path = gas->path(p);
      double T = state(p, 0);
      double J = path.J(start);
      for (long n = 0; n < steps; ++n) {
        const double J_next = path.J(start + static_cast<double>(n + 1) * dt);
        T = step_(gas->material(), J, T, J_next);
        J = J_next;
      }
      state(p, 0) = T;
    }
    statistics_ = SolverStatistics{};
    statistics_.steps = steps;
  }
  SolverStatistics statistics() const override { return statistics_; }

 private:
  std::string name_;
  int order_;
  Step step_;
  SolverStatistics statistics_;
};

}  // namespace

std::vector<UpdateInfo> temperature_updates() {
  return {{"mpm-trapezoid", 1, "NairnMPM's gas update as published: trapezoidal work at the old temperature (gas cases)"},
          {"mpm-trapezoid-corrected", 2, "the same with the new end at the new temperature, exact attraction energy (gas cases)"}};
}

std::unique_ptr<Integrator> make_temperature_update(const std::string& name) {
  if (name == "mpm-trapezoid") return std::make_unique<TemperatureUpdate>(name, 1, &nairn_temperature_step);
  if (name == "mpm-trapezoid-corrected") return std::make_unique<TemperatureUpdate>(name, 2, &trapezoid_temperature_step);
  return nullptr;
}

}  // namespace dlpverify::gas
