// Verifies this project's own steppers through dlpverify's harness and check.
//   verify_own_integrator midpoint-on-drag             own midpoint, DLP drag case: order 2
//   verify_own_integrator midpoint-on-oscillator       own midpoint, own problem: order 2
//   verify_own_integrator rk4-on-oscillator            dlpverify's RK4, own problem: order 4
//   verify_own_integrator broken-stepper-misses-order  the slipped midpoint must FAIL with an order miss
// Exit 0 when the expectation holds, 1 otherwise.
#include <cstdio>
#include <memory>
#include <string>

#include <dlpverify/check.hpp>
#include <dlpverify/dlp.hpp>
#include <dlpverify/report.hpp>
#include <dlpverify/runge_kutta.hpp>
#include <dlpverify/study.hpp>

#include "oscillator.hpp"
#include "own_steppers.hpp"

namespace {

dlpverify::CheckVerdict study(const dlpverify::Problem& problem, dlpverify::Integrator& integrator,
                              const dlpverify::StudyDefaults& defaults, double expected_order) {
  dlpverify::StudyPlan plan;
  plan.t_end = defaults.t_end;
  plan.coarsest_dt = defaults.dt;
  plan.levels = defaults.levels;
  const dlpverify::StudyResult result = dlpverify::run_study(problem, integrator, plan);
  const dlpverify::CheckVerdict verdict = dlpverify::check_orders(result, expected_order, 0.1);
  std::printf("%s on %s:\n", integrator.name().c_str(), problem.name().c_str());
  for (const std::string& finding : verdict.findings) std::printf("  %s\n", finding.c_str());
  return verdict;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "";
  const auto drag = dlpverify::dlp::make_problem("drag", {.outer = 6});
  const dlpverify::StudyDefaults drag_defaults = dlpverify::dlp::case_defaults("drag");
  const DampedOscillators oscillators(64);
  // Two periods of the slowest oscillator, 32 to 512 steps (RK4's velocity order is still 3.89
  // from 16 steps on: pre-asymptotic).
  const dlpverify::StudyDefaults oscillator_defaults{12.8, 0.4, 5};

  if (which == "midpoint-on-drag") {
    OwnMidpoint midpoint;
    return study(*drag, midpoint, drag_defaults, 2.0).passed ? 0 : 1;
  }
  if (which == "midpoint-on-oscillator") {
    OwnMidpoint midpoint;
    return study(oscillators, midpoint, oscillator_defaults, 2.0).passed ? 0 : 1;
  }
  if (which == "rk4-on-oscillator") {
    dlpverify::ExplicitRungeKutta<dlpverify::tableau::rk4> rk4("rk4");
    return study(oscillators, rk4, oscillator_defaults, 4.0).passed ? 0 : 1;
  }
  if (which == "broken-stepper-misses-order") {
    OwnMidpoint broken(true);
    const dlpverify::CheckVerdict verdict = study(*drag, broken, drag_defaults, 2.0);
    const bool order_miss = !verdict.passed && verdict.has(dlpverify::CheckOutcome::order_miss);
    std::printf("%s\n", order_miss ? "the broken stepper fails with an order miss, as it must"
                                   : "UNEXPECTED: the broken stepper was not caught by an order miss");
    return order_miss ? 0 : 1;
  }
  std::fprintf(stderr, "usage: verify_own_integrator midpoint-on-drag | midpoint-on-oscillator | rk4-on-oscillator | "
                       "broken-stepper-misses-order\n");
  return 2;
}
