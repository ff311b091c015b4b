// The DLP's fused Runge–Kutta steps (dlpverify/fused_runge_kutta.hpp): the rates of
// particle_rates inlined into the stage loops of the built-in tableaux, for the terms whose rates
// the compiler vectorises whole — C_D constant and no burning (d = d0), with or without gravity and
// heat. The C_D(Re) law and burning need SLEEF's pow and cbrt, which are calls: those kernels step
// through the block right-hand side (block_rates.hpp). (Measured: a stage loop calling SLEEF's
// vector routines per member through `omp declare simd` variants gives the same bits but runs RK2
// on `full` at 28 M/s against the block kernels' 44 M/s: each member's chain cbrt → Re → pow
// exposes the routines' latency, where the block kernels' runs of independent calls overlap.)
#pragma once

#include "dlpverify/runge_kutta.hpp"
#include "problems/dlp/rates.hpp"

namespace dlpverify::dlp {

// The stepper for `tableau` (&tableau::midpoint, …) and blocks of `block` members with the rates
// `constants` (kept alive by the caller), or an empty one where there is none.
FusedSteps dlp_fused_steps(const RateConstants& constants, const void* tableau, int block);

}  // namespace dlpverify::dlp
