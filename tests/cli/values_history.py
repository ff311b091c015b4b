"""--history rows against what docs/model.md makes derivable by hand, on gravity (§4.2: no drag,
dv/dt = g = (0, 0, -g), dx/dt = v) over the lattice cloud of §2 (x0 = (i, j, k) spacing,
1 <= |(i, j, k)| <= R_out, v0 = x0/t0, t0 = R_out spacing / u_s).

Explicit Euler, step h, from (x0, v0): v_n = v0 + n h g exactly, and
    x_n = x0 + n h v0 + h^2 g (0 + 1 + ... + n-1) = x0 + n h v0 + h^2 g n(n-1)/2,
while the exact x(t_n) = x0 + v0 t_n + g t_n^2/2 = x0 + n h v0 + h^2 g n^2/2. So every particle
is off by exactly h^2 g n/2 = g h t_n/2 along z, and the cloud's position L2 at t_n is
    L2_position(t_n) = sqrt(N) g h t_n / 2,
while its velocity error is rounding only: at most n ulp of |v| per particle, so
L2_velocity <= n eps |v|_L2 (eps = 2^-52).
RK2 (the explicit midpoint rule) is exact for constant acceleration:
x_{n+1} = x_n + h (v_n + h g/2) = x(t_{n+1}); both errors are rounding, within n eps of the sizes.
The reference's size columns are the closed form's: sqrt(sum |x(t)|^2), sqrt(sum |v(t)|^2).
usage: values_history.py DLPVERIFY
"""
import csv
import math
import sys

from values_common import check, close, finish, folder, path, run

dlpverify = sys.argv[1]
folder()

R_OUT, SPACING, US, G = 4, 1e-4, 100.0, 5.0  # --outer, --spacing (= d0, the default), --us, --g
T_END, DT0, LEVELS, OUTPUTS = 0.01, 5e-4, 3, 8
EPS = 2.0**-52
t0 = R_OUT * SPACING / US
cloud = [(i * SPACING, j * SPACING, k * SPACING)
         for i in range(-R_OUT, R_OUT + 1) for j in range(-R_OUT, R_OUT + 1) for k in range(-R_OUT, R_OUT + 1)
         if 1 <= i * i + j * j + k * k <= R_OUT * R_OUT]
N = len(cloud)
steps = round(T_END / DT0) * 2 ** (LEVELS - 1)  # the finest level: 80 steps
h = T_END / steps


def sizes(t):
    """sqrt(sum |x(t)|^2) and sqrt(sum |v(t)|^2) of the exact motion, t the time since t0."""
    x2 = math.fsum(x * x * (1 + t / t0) ** 2 + y * y * (1 + t / t0) ** 2 + (z * (1 + t / t0) - G * t * t / 2) ** 2
                   for x, y, z in cloud)
    v2 = math.fsum((x / t0) ** 2 + (y / t0) ** 2 + (z / t0 - G * t) ** 2 for x, y, z in cloud)
    return math.sqrt(x2), math.sqrt(v2)


for integrator in ("euler", "rk2"):
    run(dlpverify, "converge", "--case", "gravity", "--integrator", integrator, "--outer", R_OUT, "--us", US, "--g", G,
        "--levels", LEVELS, "--dt", DT0, "--t-end", T_END, "--history", path("h.csv"), "--history-outputs", OUTPUTS)
    rows = list(csv.DictReader(open(path("h.csv"))))
    check(list(rows[0].keys()) == ["t", "l2_position", "l2_velocity", "ref_l2_position", "ref_l2_velocity"],
          f"{integrator}: columns {list(rows[0].keys())}")
    check(len(rows) == OUTPUTS, f"{integrator}: {len(rows)} rows, expected {OUTPUTS}")
    for m, row in enumerate(rows, start=1):
        n = steps * m // OUTPUTS
        t = n * h
        close(float(row["t"]), t, 1e-15, f"{integrator} row {m}: t")
        size_x, size_v = sizes(t)
        close(float(row["ref_l2_position"]), size_x, 1e-13, f"{integrator} row {m}: reference position size")
        close(float(row["ref_l2_velocity"]), size_v, 1e-13, f"{integrator} row {m}: reference velocity size")
        if integrator == "euler":
            # The error is 3e-6 to 1.3e-5 of each particle's |x|; rounding, about n eps |x| <= 2e-14 |x|
            # after 80 steps, is within 1e-8 of it.
            close(float(row["l2_position"]), math.sqrt(N) * G * h * t / 2, 1e-8, f"euler row {m} (t = {t:.6g}): L2 position")
        else:
            check(float(row["l2_position"]) <= n * EPS * size_x,
                  f"rk2 row {m}: L2 position {row['l2_position']} above rounding {n * EPS * size_x:.3g}")
        check(float(row["l2_velocity"]) <= n * EPS * size_v,
              f"{integrator} row {m}: L2 velocity {row['l2_velocity']} above rounding {n * EPS * size_v:.3g}")

finish(f"history of euler (L2 = sqrt(N) g h t/2) and rk2 (rounding) on gravity, {OUTPUTS} rows each")
