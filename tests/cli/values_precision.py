"""dlpverify precision: the work-precision JSON's values, on drag at R_out 10 (docs/dlp.md's work-precision table).
- RK2's runs: dt_k = dt_0/2^k over t_end 0.01 s (20 * 2^k steps), two whole-cloud right-hand
  side evaluations per step (the explicit midpoint rule has two stages): rhs_evals = 2 steps;
  the least-squares slope of ln L2 against ln dt (computed here) is RK2's order 2 within 0.1.
- Adams (CVODE) runs: one per rtol, 1e-3 ... 1e-12 at one per decade, and the error of each
  variable falls strictly as rtol tightens. (CVODE bounds local error estimates, so this need not
  hold on every cloud: at R_out 4 the position error rises from 5.7e-9 at rtol 1e-8 to 1.7e-8 at
  1e-9. The documented sweep, R_out 10, falls at every decade, by a factor 1.6 at least.)
usage: values_precision.py DLPVERIFY
"""
import json
import math
import sys

import numpy as np

from values_common import check, close, finish, folder, path, run

dlpverify = sys.argv[1]
folder()

run(dlpverify, "precision", "--case", "drag", "--integrator", "rk2", "--outer", 10, "--levels", 4, "--rtol-max", "1e-3", "--rtol-min", "1e-12",
    "--per-decade", 1, "--json", path("wp.json"))
study = json.load(open(path("wp.json")))
runs = study["runs"]
variables = study["variables"]
check(variables == ["position", "velocity"], f"variables {variables}")

rk2 = [r for r in runs if "dt" in r]  # the fixed-step runs
check([r["method"] for r in rk2] == ["rk2"] * 4, f"fixed-step runs {[r['method'] for r in rk2]}, expected 4 of rk2")
for k, r in enumerate(rk2):
    close(r["dt"], 5e-4 / 2**k, 1e-15, f"rk2 run {k}: dt")
    check(r["steps"] == 20 * 2**k, f"rk2 run {k}: {r['steps']} steps, expected {20 * 2**k}")
    check(r["rhs_evals"] == 2 * r["steps"], f"rk2 run {k}: {r['rhs_evals']} RHS evaluations for {r['steps']} steps")
for v in variables:
    slope = np.polyfit([math.log(r["dt"]) for r in rk2], [math.log(r["l2_" + v]) for r in rk2], 1)[0]
    check(abs(slope - 2.0) <= 0.1, f"rk2 {v}: fitted order {slope:.4f}, expected 2 +- 0.1")

adams = [r for r in runs if r["method"] == "adams"]
rtols = [10.0**-e for e in range(3, 13)]
check(len(adams) == len(rtols), f"{len(adams)} adams runs, expected {len(rtols)}")
for r, rtol in zip(adams, rtols):
    close(r["rtol"], rtol, 1e-12, "adams run rtol")
    check(not r["reference_limited"], f"adams rtol {rtol:g}: limited by the reference")
for v in variables:
    errors = [r["l2_" + v] for r in adams]
    check(all(finer < coarser for coarser, finer in zip(errors, errors[1:])),
          f"adams {v}: L2 errors do not fall strictly with rtol: {', '.join(f'{e:.3e}' for e in errors)}")

finish("rk2: rhs_evals = 2 steps, fitted order 2; adams: error falls with rtol")
