"""A study at refinement ratio r = 3: every number that depends on r, recomputed here from the
study's own L2 errors and level differences by the formulas of docs/model.md §6 and
docs/verification.md (a hard-coded ln 2 anywhere gives orders 1.58x too large, and fails):

    pairwise order      p_k = ln(e_{k-1}/e_k) / ln r                    (k >= 1)
    self-convergence    q_k = ln(d_{k-1}/d_k) / ln r                    (k >= 2)
    Richardson          e_R = d_L / (r^q_L - 1)                         (finest level L)
    GCI                 GCI = F_s (d_L/|y|) / (r^q_L - 1),  F_s = 1.25, |y| the reference's L2 size
    fitted order        least-squares slope of ln e against ln dt over the levels used

RK2 on drag, R_out 4, t_end 0.01 s (the case's), dt_0 = 1e-3 s: 10, 30, 90 and 270 steps.
usage: values_ratio3.py DLPVERIFY
"""
import csv
import json
import math
import sys

import numpy as np

from values_common import check, close, finish, folder, path, run

dlpverify = sys.argv[1]
r = 3.0
folder()
run(dlpverify, "converge", "--case", "drag", "--integrator", "rk2", "--outer", 4, "--levels", 4, "--ratio", 3,
    "--dt", "1e-3", "--json", path("s.json"), "--csv", path("s.csv"), "--table", path("s.txt"))
study = json.load(open(path("s.json")))
levels = study["levels"]
rows = list(csv.DictReader(line for line in open(path("s.csv")) if not line.startswith("#")))
table = open(path("s.txt")).read().splitlines()

TIGHT = 1e-12  # a log, a division and a power in double precision: a few ulp

check(study["ratio"] == 3.0, f"ratio {study['ratio']}, expected 3")
check([l["steps"] for l in levels] == [10, 30, 90, 270], f"steps {[l['steps'] for l in levels]}")
for k, level in enumerate(levels):
    close(level["dt"], 0.01 / (10 * 3**k), 1e-15, f"level {k} dt")

for var in ("position", "velocity"):
    e = [l["l2_" + var] for l in levels]
    d = [l["self_difference_" + var] for l in levels]
    check([float(row["l2_" + var]) for row in rows] == e, f"{var}: the CSV's L2 errors differ from the JSON's")
    status = [l["status_by_variable"][var]["status"] for l in levels]
    window = [k for k, st in enumerate(status) if st == "ok"]
    check(all(st == "pre-asymptotic" for st in status[:window[0]]) and window == list(range(window[0], len(levels))),
          f"{var}: statuses {status}: not pre-asymptotic levels then ok ones")

    p = [None] + [math.log(e[k - 1] / e[k]) / math.log(r) for k in range(1, len(e))]
    check(levels[0]["order_" + var] is None, f"{var}: level 0 has a pairwise order")
    for k in range(1, len(levels)):
        close(levels[k]["order_" + var], p[k], TIGHT, f"{var} level {k} pairwise order (JSON)")
        close(float(rows[k]["order_" + var]), p[k], TIGHT, f"{var} level {k} pairwise order (CSV)")
    check(1.9 < p[-1] < 2.1, f"{var}: finest pairwise order {p[-1]} is not RK2's 2")

    q = [None, None] + [math.log(d[k - 1] / d[k]) / math.log(r) for k in range(2, len(d))]
    for k in range(2, len(levels)):
        close(levels[k]["self_order_" + var], q[k], TIGHT, f"{var} level {k} self-convergence order")

    sc = study["self_convergence"][var]
    size = levels[-1]["norms_" + var]["solution_l2"]
    richardson = d[-1] / (r ** q[-1] - 1.0)
    gci = 1.25 * (d[-1] / size) / (r ** q[-1] - 1.0)
    close(sc["order"], q[-1], TIGHT, f"{var} self-convergence order of the finest level")
    close(sc["richardson_error"], richardson, TIGHT, f"{var} Richardson estimate")
    close(sc["gci"], gci, TIGHT, f"{var} GCI")
    check(sc["gci_safety_factor"] == 1.25, f"{var} GCI safety factor {sc['gci_safety_factor']}")

    used = study["fitted_order"][var]["levels_used"]
    check(used == window and len(used) >= 3, f"{var}: fit over levels {used}, the ok levels are {window}")
    slope = np.polyfit([math.log(levels[k]["dt"]) for k in used], [math.log(e[k]) for k in used], 1)[0]
    close(study["fitted_order"][var]["value"], slope, 1e-10, f"{var} fitted order")

    # The table prints the same numbers rounded: rates %.2f, self-convergence %.3f,
    # Richardson %.3e, GCI %.2e.
    column = {"position": 5, "velocity": 8}[var]
    printed = [line.split() for line in table if "|" in line and line.split()[0] in ("1", "2", "3")]
    for k, fields in zip((1, 2, 3), printed):
        check(abs(float(fields[column]) - p[k]) <= 0.005 + 1e-12, f"{var} level {k} table rate {fields[column]}, computed {p[k]:.6f}")
    line = next((l for l in table if l.startswith(f"{var:<12s} self-convergence order")), "")
    words = line.replace(";", " ").replace(",", " ").replace(")", " ").split()
    try:
        shown_order = float(words[3])
        shown_richardson = float(words[words.index("error") + 1])
        shown_gci = float(words[words.index("GCI") + 1])
    except (IndexError, ValueError):
        check(False, f"{var}: no self-convergence line in the table")
        continue
    check(abs(shown_order - q[-1]) <= 0.0005 + 1e-12, f"{var} table self-convergence order {shown_order}, computed {q[-1]:.6f}")
    close(shown_richardson, richardson, 5e-4, f"{var} table Richardson estimate")
    close(shown_gci, gci, 5e-3, f"{var} table GCI")

finish("ratio 3: pairwise and self-convergence orders, Richardson, GCI and the fit from the errors")
