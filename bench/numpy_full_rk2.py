#!/usr/bin/python3
"""The `full` physics (C_D(Re) law, gravity, heat, burning: docs/model.md §1) stepped with the
explicit midpoint rule in whole-array numpy, for the README's comparison with `dlpverify bench`.

    /usr/bin/python3 bench/numpy_full_rk2.py [PARTICLES] [STEPS]

Prints particle-steps per second. Written from docs/model.md and the default parameters of
docs/model.md §8, independently of the C++ code.
"""
import sys
import time

import numpy as np

RHO_P, CS, T_P0 = 2700.0, 900.0, 1500.0
RHO_A, MU_A, CP, PR, T_A = 1.2, 1.8e-5, 1005.0, 0.72, 300.0
G, C_B, D0 = 9.81, 10.0, 1e-4
K_A = MU_A * CP / PR


def rates(y):
    """dy/dt of every particle: y is 8 × N (x, y, z, vx, vy, vz, T, m)."""
    v, T, m = y[3:6], y[6], y[7]
    d = np.cbrt(6.0 * m / (np.pi * RHO_P))
    slip = np.sqrt((v * v).sum(axis=0))
    re = RHO_A * slip * d / MU_A
    with np.errstate(divide="ignore", invalid="ignore"):
        law = np.where(re > 0.0, 28.0 * re**-0.85 * slip, 0.0)  # C_D(Re)‖w‖ = 0.48‖w‖ + 28 Re^−0.85 ‖w‖
    drag = -(3.0 * RHO_A / (4.0 * RHO_P * d)) * (0.48 * slip + law)
    out = np.empty_like(y)
    out[0:3] = v
    out[3:6] = drag * v
    out[5] -= G
    nusselt = 2.0 + 0.6 * np.cbrt(PR) * np.sqrt(re)
    out[6] = np.pi * d * K_A * nusselt * (T_A - T) / (m * CS)
    out[7] = -C_B * d * d
    return out


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
    steps = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    rng = np.random.default_rng(1)
    y = np.empty((8, n))
    y[0:3] = rng.uniform(-0.01, 0.01, (3, n))
    y[3:6] = rng.uniform(-100.0, 100.0, (3, n))
    y[6] = T_P0
    y[7] = np.pi * RHO_P * D0**3 / 6.0
    dt = 1e-6
    start = time.perf_counter()
    for _ in range(steps):
        y = y + dt * rates(y + 0.5 * dt * rates(y))  # the explicit midpoint rule
    seconds = time.perf_counter() - start
    print(f"numpy full RK2: {n * steps / seconds / 1e6:.2f} M particle-steps/s ({n} particles, {steps} steps)")


if __name__ == "__main__":
    main()
