"""dlpverify stagger: the measured contraction of the staggered iteration against its spectral
radius computed here (docs/model.md §7.3), and Algorithm 7.1's counts pinned to their measured
values. The contraction mode exits 0 whatever it measures, so only these values can fail it.

Backward Euler on a w1' + w2 = 0, b w2' + w1 = 0: a Jacobi sweep's iteration matrix is
-[[0, dt/a], [dt/b, 0]], eigenvalues +-dt/sqrt(ab), so the contraction per sweep is dt/sqrt(ab);
a Gauss-Seidel sweep's, on its range, dt^2/(ab). For a w1' + w2 = 0, b w2' + w3 = 0,
c w3'' + w1 = 0 the Jacobi matrix is a 3-cycle with lambda^3 = dt^4/(abc): (dt^4/|abc|)^(1/3);
Gauss-Seidel's the square root of dt^4/|abc| (the (w2, w3) pair is a 2-cycle).
usage: values_stagger.py DLPVERIFY
"""
import csv
import json
import math
import sys

from values_common import check, close, finish, folder, path, run

dlpverify = sys.argv[1]
folder()

# The measured contraction is the exact radius to round-off (docs/model.md §7.3.1: 1e-16 to 1e-12).
CONTRACTION = 1e-10


def jacobi_2x2(dt, a, b, c):
    return dt / math.sqrt(a * b)


def gauss_seidel_2x2(dt, a, b, c):
    return dt**2 / (a * b)


def jacobi_3x3(dt, a, b, c):
    return (dt**4 / abs(a * b * c)) ** (1.0 / 3.0)


def gauss_seidel_3x3(dt, a, b, c):
    return (dt**4 / abs(a * b * c)) ** 0.5


# case, sweep, (a, b, c) (None: the case's own, docs/model.md: a = 2, b = 0.5, c = 1), steps, radius
studies = [
    ("stagger-2x2", "jacobi", None, (0.3, 0.6, 0.9), jacobi_2x2),
    ("stagger-2x2", "jacobi", (3.0, 1.2, None), (0.5, 1.0, 1.5, 1.7), jacobi_2x2),
    ("stagger-2x2", "gauss-seidel", (3.0, 1.2, None), (0.5, 1.0, 1.5), gauss_seidel_2x2),
    ("stagger-3x3", "jacobi", None, (0.3, 0.6, 0.9), jacobi_3x3),
    ("stagger-3x3", "gauss-seidel", None, (0.3, 0.6, 0.9), gauss_seidel_3x3),
    ("stagger-3x3", "jacobi", (1.5, 0.8, 2.5), (0.4, 0.8, 1.2), jacobi_3x3),
]
for case, sweep, constants, steps, radius in studies:
    args = ["stagger", "--case", case, "--sweep", sweep, "--dt", ",".join(map(str, steps))]
    a, b, c = 2.0, 0.5, 1.0
    if constants:
        a, b = constants[0], constants[1]
        args += ["--a", a, "--b", b]
        if constants[2] is not None:
            c = constants[2]
            args += ["--c", c]
    label = f"{case} {sweep} a={a} b={b}" + (f" c={c}" if case == "stagger-3x3" else "")
    run(dlpverify, *args, "--json", path("c.json"), "--csv", path("c.csv"), "--table", path("c.txt"))
    rows = json.load(open(path("c.json")))["rows"]
    csv_rows = list(csv.DictReader(open(path("c.csv"))))
    table = open(path("c.txt")).read().splitlines()
    check(len(rows) == len(csv_rows) == len(steps), f"{label}: {len(rows)} JSON and {len(csv_rows)} CSV rows for {len(steps)} steps")
    printed = [line.split() for line in table if line.split() and line.split()[-1] == "converged"]
    check(len(printed) == len(steps), f"{label}: {len(printed)} converged rows in the table for {len(steps)} steps")
    for row, csv_row, dt, shown in zip(rows, csv_rows, steps, printed):
        expected = radius(dt, a, b, c)
        close(row["dt"], dt, 0.0, f"{label}: row dt")
        close(row["contraction"], expected, CONTRACTION, f"{label} dt={dt}: contraction")
        close(float(csv_row["contraction"]), expected, CONTRACTION, f"{label} dt={dt}: contraction (CSV)")
        close(row["spectral_radius"], expected, 1e-14, f"{label} dt={dt}: spectral radius")
        check(row["converged"] and not row["diverged"], f"{label} dt={dt}: not converged")
        # the table: dt, sweeps, contraction and radius (%.10f), relative difference
        check(abs(float(shown[2]) - expected) <= 5e-11 + 1e-15, f"{label} dt={dt}: table contraction {shown[2]}, expected {expected:.12f}")

# Algorithm 7.1 on stagger-2x2 from dt = 1.5 over 1 s (docs/cooling.md, "Algorithm 7.1"): steps
# taken, rejected for the staggering tolerance and for the local error, total sweeps, as measured;
# the largest step and the error at the end as docs/cooling.md rounds them; every accepted step below
# the limit sqrt(ab) = 1 and the error at the end within 10 TOL.
table_7_1 = {
    1e-3: (618, 1, 6, 1879, "1.8e-03", "8.1e-04"),
    1e-4: (6173, 1, 7, 18551, "1.8e-04", "8.1e-05"),
    1e-5: (61728, 1, 7, 185216, "2.0e-05", "8.1e-06"),
}
for tol, (taken, rejected_staggering, rejected_error, sweeps, largest, error) in table_7_1.items():
    run(dlpverify, "stagger", "--case", "stagger-2x2", "--adaptive", "--dt", 1.5, "--tol", tol, "--json", path("a.json"),
        "--csv", path("a.csv"), "--table", path("a.txt"))
    result = json.load(open(path("a.json")))
    counts = tuple(result[k] for k in ("steps_taken", "steps_rejected_staggering", "steps_rejected_error", "total_sweeps"))
    csv_counts = tuple(int(next(csv.DictReader(open(path("a.csv"))))[k])
                       for k in ("steps_taken", "steps_rejected_staggering", "steps_rejected_error", "total_sweeps"))
    check(csv_counts == counts, f"TOL {tol:g}: CSV counts {csv_counts}, JSON {counts}")
    table = open(path("a.txt")).read()
    check(f"steps taken      {taken}\n" in table and f"total sweeps     {sweeps}\n" in table,
          f"TOL {tol:g}: the table does not show {taken} steps and {sweeps} sweeps")
    check(counts == (taken, rejected_staggering, rejected_error, sweeps),
          f"TOL {tol:g}: steps, rejected (staggering, error), sweeps {counts}, measured {(taken, rejected_staggering, rejected_error, sweeps)}")
    check(f"{result['largest_step']:.1e}" == largest, f"TOL {tol:g}: largest step {result['largest_step']:.3e}, measured {largest}")
    check(f"{result['error_at_end']:.1e}" == error, f"TOL {tol:g}: error at the end {result['error_at_end']:.3e}, measured {error}")
    check(result["largest_step"] < math.sqrt(2.0 * 0.5), f"TOL {tol:g}: largest step {result['largest_step']} not below 1")
    check(result["error_at_end"] <= 10 * tol, f"TOL {tol:g}: error at the end {result['error_at_end']} above 10 TOL")
    check(result["passed"], f"TOL {tol:g}: not passed")

# The source's control alone (--no-error-control) over 5 s: 12 steps, 9 restarts, 202 sweeps.
run(dlpverify, "stagger", "--case", "stagger-2x2", "--adaptive", "--dt", 1.5, "--no-error-control", "--t-end", 5,
    "--json", path("n.json"), "--csv", path("n.csv"), "--table", path("n.txt"))
result = json.load(open(path("n.json")))
counts = tuple(result[k] for k in ("steps_taken", "steps_rejected_staggering", "steps_rejected_error", "total_sweeps"))
check(counts == (12, 9, 0, 202), f"--no-error-control: steps, rejected (staggering, error), sweeps {counts}, measured (12, 9, 0, 202)")
check(result["largest_step"] < 1.0, f"--no-error-control: largest step {result['largest_step']} not below 1")
check("total sweeps     202\n" in open(path("n.txt")).read(), "--no-error-control: the table does not show 202 sweeps")
check(int(next(csv.DictReader(open(path("n.csv"))))["total_sweeps"]) == 202, "--no-error-control: the CSV does not show 202 sweeps")

finish("contraction = spectral radius for both systems and sweeps; Algorithm 7.1's counts as measured")
