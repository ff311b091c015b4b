#!/usr/bin/env python3
"""An independent implementation of docs/model.md §2, §3, §4.3 and §5 (numpy, whole-array stages),
written from the spec alone, that recomputes the L2 norms of a dlpverify drag study from its
JSON and fails unless every level agrees to 1e-6 relative.

usage: independent_drag.py STUDY.json
"""
import json
import math
import sys

import numpy as np

TABLEAUX = {  # (a, b, c) of docs/model.md §3's fixed-step methods
    "euler": ([[0.0]], [1.0], [0.0]),
    "rk2": ([[0.0, 0.0], [0.5, 0.0]], [0.0, 1.0], [0.0, 0.5]),
    "heun": ([[0.0, 0.0], [1.0, 0.0]], [0.5, 0.5], [0.0, 1.0]),
    "rk4": ([[0, 0, 0, 0], [0.5, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 1, 0]], [1 / 6, 1 / 3, 1 / 3, 1 / 6], [0, 0.5, 0.5, 1]),
}


def lattice(outer, inner, spacing):
    r = np.arange(-outer, outer + 1)
    i, j, k = np.meshgrid(r, r, r, indexing="ij")
    r2 = i * i + j * j + k * k
    keep = (r2 >= inner * inner) & (r2 <= outer * outer)
    return np.stack([i[keep], j[keep], k[keep]], axis=1).astype(float) * spacing


def main(path):
    study = json.load(open(path))
    o = study["options"]
    assert study["case"] == "drag", "this cross-check covers the drag case"
    spacing = o["spacing"]
    x0 = lattice(o["outer"], o["inner"], spacing)
    t0 = o["outer"] * spacing / o["us"]
    v0 = (np.linalg.norm(x0, axis=1) / (o["us"] * t0))[:, None] * o["us"] * np.divide(
        x0, np.linalg.norm(x0, axis=1)[:, None], out=np.zeros_like(x0), where=np.linalg.norm(x0, axis=1)[:, None] > 0)
    K = 3 * o["rho-gas"] * o["cd"] / (4 * o["rho-p"] * o["diameter"])

    def f(y):  # y = [x | v], dv/dt = -K |v| v
        v = y[:, 3:]
        return np.hstack([v, -K * np.linalg.norm(v, axis=1)[:, None] * v])

    tau = o["t-end"]
    s0 = np.linalg.norm(v0, axis=1)
    unit = np.divide(v0, s0[:, None], out=np.zeros_like(v0), where=s0[:, None] > 0)
    x_exact = x0 + unit * (np.log1p(K * s0 * tau) / K)[:, None]
    v_exact = unit * (s0 / (1 + K * s0 * tau))[:, None]

    a, b, _ = TABLEAUX[study["integrator"]]
    worst = 0.0
    assert len(study["levels"]) == o["levels"]
    for level in study["levels"]:
        n, dt = level["steps"], tau / level["steps"]
        y = np.hstack([x0, v0])
        for _ in range(n):
            k = []
            for i in range(len(b)):
                stage = y.copy()
                for j in range(i):
                    if a[i][j] != 0.0:
                        stage += dt * a[i][j] * k[j]
                k.append(f(stage))
            for i in range(len(b)):
                if b[i] != 0.0:
                    y = y + dt * b[i] * k[i]
        ex = math.sqrt(np.sum((y[:, :3] - x_exact) ** 2))
        ev = math.sqrt(np.sum((y[:, 3:] - v_exact) ** 2))
        # Two implementations round differently (summation order, fused stages): their states may
        # differ by about eps*steps*|y|, which bounds how closely tiny errors (RK4) can agree.
        eps = np.finfo(float).eps
        for name, mine, theirs, size in (("position", ex, level["l2_position"], np.linalg.norm(x_exact)),
                                         ("velocity", ev, level["l2_velocity"], np.linalg.norm(v_exact))):
            allowed = 1e-6 * abs(mine) + eps * n * size
            score = abs(mine - theirs) / allowed  # <= 1 passes
            worst = max(worst, score)
            print(f"level {level['level']} {name}: independent {mine:.12e} dlpverify {theirs:.12e} "
                  f"rel diff {abs(mine - theirs) / abs(mine):.2e} ({score:.3f} of allowed)")
    print(f"{len(x0)} particles; worst difference {worst:.3f} of allowed (1e-6 relative + eps*steps*|y|)")
    return 0 if worst <= 1.0 and len(x0) == study["particles"] else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
