#!/usr/bin/env python3
"""A particle code of its own that dlpverify does not drive: it runs, it writes its final state.

N tracer particles of response time tau in a steady swirl u(x, y) = omega (-y, x), with gravity
along -z, each obeying

    dx/dt = v,    dv/dt = (u(x) - v) / tau + g

integrated by Heun's method (second order) or, with --euler, by forward Euler (first order). The
initial state is made here from a fixed seed, so every run starts from the same particles. The
final state goes to an HDF5 file in dlpverify's exchange format (docs/exchange.md, docs/analyze.md):
/fields/<name> float64 with a `unit`, the step and times as root attributes; or, with --csv, to a
CSV with an id column, its rows in an order of its own (as a parallel code's gather may write them).

    python3 particles.py --steps 100 --out runs/run-100.h5

then, for five step counts:  dlpverify analyze runs/run-*.h5 --variables variables.toml
"""
import argparse

import h5py
import numpy as np

NAMES = ["x", "y", "z", "vx", "vy", "vz"]
UNITS = ["m", "m", "m", "m/s", "m/s", "m/s"]
OMEGA, TAU, GRAVITY = 2.0, 0.05, 9.81  # 1/s, s, m/s^2
T_END = 0.5  # s


def initial_state(members):
    rng = np.random.default_rng(27)  # a fixed seed: the same particles in every run
    position = rng.uniform(-1.0, 1.0, size=(3, members))
    velocity = rng.normal(0.0, 0.5, size=(3, members))
    return np.vstack([position, velocity])


def rates(y):
    x, yy, _, vx, vy, vz = y
    return np.vstack([vx, vy, vz, (-OMEGA * yy - vx) / TAU, (OMEGA * x - vy) / TAU, -vz / TAU - GRAVITY])


def integrate(y, dt, steps, euler):
    for _ in range(steps):
        k1 = rates(y)
        y = y + dt * k1 if euler else y + 0.5 * dt * (k1 + rates(y + dt * k1))
    return y


def write_hdf5(path, y, dt, steps):
    with h5py.File(path, "w") as f:
        f.attrs["dlpverify_exchange_version"] = 1
        f.attrs.update({"t0": 0.0, "dt": dt, "steps": steps, "t_end": steps * dt})
        f.attrs["fields"] = NAMES
        for name, unit, column in zip(NAMES, UNITS, y):
            f.create_dataset("fields/" + name, data=column, dtype="f8").attrs["unit"] = unit


def write_csv(path, y):
    order = np.random.default_rng(len(path)).permutation(y.shape[1])  # any row order: the id matches
    with open(path, "w") as f:
        f.write("# units: 1," + ",".join(UNITS) + "\n")
        f.write("id," + ",".join(NAMES) + "\n")
        for p in order:
            f.write("%d," % p + ",".join(repr(float(v)) for v in y[:, p]) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, required=True, help="steps over t_end = %g s" % T_END)
    parser.add_argument("--out", required=True, help="the run file (.h5, or .csv with --csv)")
    parser.add_argument("--members", type=int, default=1000)
    parser.add_argument("--euler", action="store_true", help="forward Euler (order 1) instead of Heun (order 2)")
    parser.add_argument("--csv", action="store_true", help="write CSV with an id column instead of HDF5")
    args = parser.parse_args()
    dt = T_END / args.steps
    y = integrate(initial_state(args.members), dt, args.steps, args.euler)
    (write_csv if args.csv else write_hdf5)(*((args.out, y) if args.csv else (args.out, y, dt, args.steps)))


if __name__ == "__main__":
    main()
