"""--per-particle: each particle's finest-level error, whose quadrature sum is the study's L2 norm
(docs/model.md §5: L2 = sqrt(sum_p |y_p - y_p(t)|^2)), so sqrt(sum err^2) over the rows must equal
the finest level's L2 in the JSON, per variable; and the rows are the lattice cloud of
docs/model.md §2, with xi = |(i, j, k)| / R_out for every lattice point 1 <= |(i, j, k)| <= R_out.
Two cases: burn (position, velocity, temperature, mass against the closed form) and full (every
term, against CVODE).
usage: values_per_particle.py DLPVERIFY
"""
import csv
import json
import math
import sys

from values_common import check, close, finish, folder, path, run

dlpverify = sys.argv[1]
folder()

R_OUT = 4
lattice_xi = sorted(math.sqrt(i * i + j * j + k * k) / R_OUT
                    for i in range(-R_OUT, R_OUT + 1) for j in range(-R_OUT, R_OUT + 1) for k in range(-R_OUT, R_OUT + 1)
                    if 1 <= i * i + j * j + k * k <= R_OUT * R_OUT)

for case in ("burn", "full"):
    run(dlpverify, "converge", "--case", case, "--outer", R_OUT, "--levels", 3, "--json", path("s.json"),
        "--per-particle", path("p.csv"))
    study = json.load(open(path("s.json")))
    rows = list(csv.DictReader(open(path("p.csv"))))
    variables = ["position", "velocity", "temperature", "mass"]
    check(list(rows[0].keys()) == ["particle", "xi"] + ["err_" + v for v in variables], f"{case}: columns {list(rows[0].keys())}")
    check(len(rows) == len(lattice_xi) == study["particles"],
          f"{case}: {len(rows)} rows, {study['particles']} particles, the lattice has {len(lattice_xi)}")
    check([int(row["particle"]) for row in rows] == list(range(len(rows))), f"{case}: particles not numbered 0…N-1")
    xi = sorted(float(row["xi"]) for row in rows)
    check(len(xi) == len(lattice_xi) and all(abs(a - b) <= 1e-15 for a, b in zip(xi, lattice_xi)),
          f"{case}: the rows' xi are not the lattice's |(i, j, k)|/R_out")
    finest = study["levels"][-1]
    for v in variables:
        errors = [float(row["err_" + v]) for row in rows]
        check(all(e >= 0.0 for e in errors), f"{case}: a negative {v} error")
        l2 = math.sqrt(math.fsum(e * e for e in errors))
        close(l2, finest["l2_" + v], 1e-12, f"{case} {v}: sqrt(sum err^2) against the finest level's L2")
        close(max(errors), finest["norms_" + v]["max"], 1e-14, f"{case} {v}: the largest row against the max norm")

finish("per-particle rows: the lattice's xi, sqrt(sum err^2) = the finest L2, max = the max norm")
