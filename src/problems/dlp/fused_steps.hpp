// The DLP's fused Runge–Kutta steps (dlpverify/fused_runge_kutta.hpp): the rates of
// particle_rates inlined into the stage loops of the built-in tableaux, for the terms whose rates
// the compiler vectorises whole — C_D constant and no burning (d = d0), with or without gravity and
// heat. The C_D(Re) law and burning need SLEEF's pow and cbrt, which are calls: those kernels step
// through the block right-hand side (block_rates.hpp).
#pragma once

#include "dlpverify/problem.hpp"
#include "problems/dlp/rates.hpp"

namespace dlpverify {

// The stepper for `tableau` (&tableau::midpoint, …) and blocks of `block` members with the rates
// `constants` (kept alive by the caller), or an empty one where there is none.
FusedSteps dlp_fused_steps(const RateConstants& constants, const void* tableau, int block);

}  // namespace dlpverify
