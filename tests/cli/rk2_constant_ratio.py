#!/usr/bin/env python3
"""The ratio of two 2-stage, second-order tableaux' error constants on `drag`, in closed form
(docs/model.md §4.3: per particle s' = -K s^2, x' = s along the launch direction).

The local error of a step h (numerical minus exact) of an explicit 2-stage RK method of order 2 is
h^3 [(sum b_i c_i^2/2 - 1/6) f''(f,f) + (sum b_i a_ij c_j - 1/6) f'f'f], and sum b_i a_ij c_j = 0
for two stages. With y = (x, s), f = (s, -K s^2): f''(f,f) = (0, -2K^3 s^4) and
f'f'f = (2K^2 s^3, -4K^3 s^4), so the local error is h^3 (-K^2 s^3/3, C K^3 s^4) with
C = 1 - sum b_i c_i^2 (midpoint 3/4, Heun 1/2). The global error h^2 E(t) solves
E_s' = -2K s E_s + C K^3 s^4, E_x' = E_s - K^2 s^3/3; with s = s0/tau, tau = 1 + K s0 t and
a = 1 - 1/tau at t_end:

    E_s = C K^2 s0^3 a (1 - a)^2,      E_x = K s0^2 (C a^2/2 - a (2 - a)/6).

The velocity ratio is C_B/C_A for every particle; the position ratio is the ratio of the L2 sums
of E_x over the cloud (the lattice points 1 <= |ijk| <= R_out, s0 = u_s |ijk|/R_out; 3.672 for
Heun over midpoint at R_out 4, where the midpoint rule's two terms nearly cancel on the outer
particles). The studies' constants are geometric means of e_k/dt_k^2 over their levels, whose
ratios rho_k still move with dt (the next term of the error, one power of dt higher); so:

- |C_B/C_A - ratio| <= max(rho) - min(rho), the spread of the studies' own level ratios;
- the finest level's ratio lies within 2 |rho_L - rho_{L-1}| of the closed form (a distance that
  halves a level is at most the last step away from its limit; 2 for room).

usage: rk2_constant_ratio.py A.json B.json A.toml B.toml
"""
import json
import math
import sys
import tomllib


def stage_constant(tableau_file):
    tableau = tomllib.load(open(tableau_file, "rb"))
    assert len(tableau["b"]) == 2 and tableau["c"][0] == 0 and tableau["A"][1][0] == tableau["c"][1], tableau
    return 1 - sum(b * c * c for b, c in zip(tableau["b"], tableau["c"]))


def speeds(options):
    """Launch speeds of the sphere cloud: s0 = u_s |ijk| / R_out."""
    outer, inner = options["outer"], options["inner"]
    assert options["shape"] == "sphere" and options["spacing"] == options["diameter"], options
    n = int(outer)
    radii = [math.sqrt(i * i + j * j + k * k) for i in range(-n, n + 1) for j in range(-n, n + 1)
             for k in range(-n, n + 1) if inner * inner <= i * i + j * j + k * k <= outer * outer]
    return [options["us"] * r / outer for r in radii]


def closed_form_ratios(study, constant_a, constant_b):
    options = study["options"]
    drag = 3 * options["rho-gas"] * options["cd"] / (4 * options["rho-p"] * options["diameter"])
    cloud = speeds(options)
    assert len(cloud) == study["particles"], (len(cloud), study["particles"])

    def position(constant, s0):
        a = 1 - 1 / (1 + drag * s0 * study["t_end"])
        return drag * s0 * s0 * (constant * a * a / 2 - a * (2 - a) / 6)

    def norm(constant):
        return math.sqrt(sum(position(constant, s0) ** 2 for s0 in cloud))

    return {"position": norm(constant_b) / norm(constant_a), "velocity": constant_b / constant_a}


def main():
    a, b = (json.load(open(f)) for f in sys.argv[1:3])
    assert a["case"] == b["case"] == "drag" and a["options"]["outer"] == b["options"]["outer"]
    expected = closed_form_ratios(a, *(stage_constant(f) for f in sys.argv[3:5]))
    for name, closed in expected.items():
        ratio = b["error_constant"][name]["value"] / a["error_constant"][name]["value"]
        rho = [lb["l2_" + name] / la["l2_" + name] for la, lb in zip(a["levels"], b["levels"])]
        spread, last_step = max(rho) - min(rho), abs(rho[-1] - rho[-2])
        print(f"{name}: constants' ratio {ratio:.4f}, closed form {closed:.4f}; level ratios "
              f"{', '.join(f'{r:.4f}' for r in rho)} (spread {spread:.4f})")
        assert abs(ratio - closed) <= spread, (name, ratio, closed, spread)
        assert abs(rho[-1] - closed) <= 2 * last_step, (name, rho[-1], closed, last_step)


if __name__ == "__main__":
    main()
