#include "problems/dlp/fused_steps.hpp"

#include <array>
#include <utility>

#include "dlpverify/fused_runge_kutta.hpp"
#include "dlpverify/runge_kutta.hpp"

namespace dlpverify::dlp {

namespace {

constexpr int kBlock = ExplicitRungeKutta<tableau::midpoint>::kBlock;  // every tableau's block

// One particle's rates for the fused stage loops: the speed is computed here (one sqrt, which the
// compiler vectorises), the diameter is d0.
template <bool Drag, bool Gravity, bool Heat>
struct Lane {
  static constexpr int kFields = dlp::kFields;
  static constexpr std::array<bool, kFields> kActive{true, true, true, true, true, true, Heat, false};
  RateConstants c;
  void operator()(double /*t*/, const double* y, double* r) const {
    particle_rates<Drag, false, Gravity, Heat, false>(c, y, (Drag || Heat) ? speed(y) : 0.0, c.diameter0, 0.0, r);
  }
};

template <const auto& Tableau, bool Drag, bool Gravity, bool Heat>
void run(const void* rates, double* const* y, int count, double t0, double dt, long steps) {
  // A copy on the stack: the stores to y cannot alias it, so the constants stay in registers.
  const Lane<Drag, Gravity, Heat> lane{*static_cast<const RateConstants*>(rates)};
  fused_runge_kutta_steps<Tableau, Lane<Drag, Gravity, Heat>, kBlock>(lane, y, count, t0, dt, steps);
}

using Run = decltype(FusedSteps::run);

// Index: drag 1, gravity 2, heat 4.
template <const auto& Tableau, int... Bits>
Run pick(int bits, std::integer_sequence<int, Bits...>) {
  static constexpr Run table[] = {&run<Tableau, (Bits & 1) != 0, (Bits & 2) != 0, (Bits & 4) != 0>...};
  return table[bits];
}

template <const auto& Tableau>
Run pick(int bits) {
  return pick<Tableau>(bits, std::make_integer_sequence<int, 8>{});
}

}  // namespace

FusedSteps dlp_fused_steps(const RateConstants& c, const void* tableau, int block) {
  const Terms& t = c.terms;
  if (block != kBlock || t.burning || (t.drag && t.drag_law == DragLaw::reynolds)) return {};
  const int bits = (t.drag ? 1 : 0) | (t.gravity ? 2 : 0) | (t.heat ? 4 : 0);
  Run run = nullptr;
  if (tableau == &tableau::euler) run = pick<tableau::euler>(bits);
  if (tableau == &tableau::midpoint) run = pick<tableau::midpoint>(bits);
  if (tableau == &tableau::heun) run = pick<tableau::heun>(bits);
  if (tableau == &tableau::rk4) run = pick<tableau::rk4>(bits);
  return {run, &c};
}

}  // namespace dlpverify::dlp
