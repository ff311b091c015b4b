#!/usr/bin/env python3
"""An external integrator for dlpverify: explicit midpoint (RK2) on the DLP cloud and the gas parcels.

It knows nothing of dlpverify but the exchange file (docs/exchange.md): it reads the initial state
and the problem's description from INPUT, integrates `steps` steps of `dt` from `t0`, and writes
the final state to OUTPUT. The right-hand side is written here from docs/model.md §1, on purpose
independently of dlpverify's own code: that is what a user's code is.

    dlpverify check --case drag --expect-order 2 \\
        --integrator "exec:python3 midpoint.py {input} {output}"

--rtol is accepted and ignored (the steps are fixed): `--tolerances` with "--rtol {rtol}" fails its
check, as it should.

--slip puts the midpoint stage at the full step (y + dt f instead of y + dt/2 f): a deliberate bug
that drops the order to 1, for the test that a check catches it.
"""
import argparse
import sys

import h5py
import numpy as np


def read_problem(path):
    with h5py.File(path, "r") as f:
        if int(f.attrs["dlpverify_exchange_version"]) != 1:
            sys.exit("midpoint.py: exchange version %s, this program reads 1" % f.attrs["dlpverify_exchange_version"])
        problem = f.attrs["problem"]
        if problem not in ("dlp", "gas"):
            sys.exit("midpoint.py: problem %s; this example implements dlp and gas" % problem)
        plan = {k: f.attrs[k] for k in ("t0", "dt", "steps")}
        if problem == "gas":  # each parcel's deepest compression, for its path J(tau)
            plan["j_min"] = f["members"]["j_min"][...]
        parameters = {k: float(v) for k, v in f["parameters"].attrs.items() if not k.endswith("_unit")}
        terms = dict(f["terms"].attrs.items())
        names = list(f.attrs["fields"])
        y = {name: f["fields"][name][...] for name in names}
        # the run's times and the fields' units, written back with the state: the output is then
        # a run file `dlpverify analyze` reads too (docs/analyze.md)
        plan["run"] = {k: f.attrs[k] for k in ("t0", "dt", "steps", "t_end", "fields", "field_units")}
    return problem, plan, parameters, terms, names, y


def make_gas_rhs(p, t0, j_min):
    """dT/dt of docs/model.md §7.1 along each parcel's path: -(gamma - 1) T J'(tau) / (J - b')."""
    period = p["period"]

    def rhs(t, y):
        tau = t - t0
        s = np.sin(np.pi * tau / period)
        J = 1.0 - (1.0 - j_min) * s * s
        J_rate = -(1.0 - j_min) * (np.pi / period) * np.sin(2.0 * np.pi * tau / period)
        return {"T": -(p["gamma"] - 1.0) * y["T"] * J_rate / (J - p["b_prime"])}

    return rhs


def make_rhs(p, terms):
    """dy/dt of docs/model.md §1 in a quiescent gas (w = -v), every term as the file switches it."""
    rho_a, rho_p, mu = p["rho_gas"], p["rho_particle"], p["mu_gas"]
    k_gas = mu * p["cp_gas"] / p["prandtl"]  # gas conductivity k_a = mu_a c_p / Pr

    def rhs(_t, y):  # the gas is steady: the rates do not depend on t
        vx, vy, vz, T, m = y["vx"], y["vy"], y["vz"], y["T"], y["m"]
        if terms["burning"] == "on":
            d = np.cbrt(6.0 * m / (np.pi * rho_p))  # the diameter follows the mass
        else:
            d = np.full_like(m, p["diameter"])
        s = np.sqrt(vx * vx + vy * vy + vz * vz)  # slip speed |w| = |v|
        zero = np.zeros_like(vx)
        ax, ay, az = zero.copy(), zero.copy(), zero.copy()
        if terms["drag"] != "off":
            if terms["drag"] == "constant":
                cd_s = p["cd"] * s
            else:  # C_D(Re) |w| = 0.48 |w| + 28 (rho_a d / mu)^-0.85 |w|^0.15: finite at |w| = 0
                cd_s = 0.48 * s + 28.0 * (rho_a * d / mu) ** -0.85 * s ** 0.15
            k = -3.0 * rho_a / (4.0 * rho_p * d) * cd_s
            ax, ay, az = k * vx, k * vy, k * vz
        if terms["gravity"] == "on":
            az = az - p["gravity"]  # g = (0, 0, -|g|)
        dT = zero
        if terms["heat"] == "on":
            reynolds = rho_a * s * d / mu
            nusselt = 2.0 + 0.6 * np.cbrt(p["prandtl"]) * np.sqrt(reynolds)
            dT = np.pi * d * k_gas * nusselt * (p["t_gas"] - T) / (m * p["cs_particle"])
        dm = -p["burn_rate"] * d * d if terms["burning"] == "on" else zero
        return {"x": vx, "y": vy, "z": vz, "vx": ax, "vy": ay, "vz": az, "T": dT, "m": dm}

    return rhs


def midpoint(rhs, y, t0, dt, steps, slip):
    stage = dt if slip else 0.5 * dt
    for n in range(steps):
        t = t0 + n * dt  # step n starts at t0 + n dt
        k1 = rhs(t, y)
        half = {name: y[name] + stage * k1[name] for name in y}
        k2 = rhs(t + stage, half)
        y = {name: y[name] + dt * k2[name] for name in y}
    return y


def write_state(path, names, y, run):
    with h5py.File(path, "w") as f:
        f.attrs["dlpverify_exchange_version"] = 1
        for key, value in run.items():
            f.attrs[key] = value
        fields = f.create_group("fields")
        for name, unit in zip(names, run["field_units"]):
            fields.create_dataset(name, data=y[name], dtype="f8").attrs["unit"] = unit


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--slip", action="store_true", help="the deliberate bug: midpoint stage at the full step")
    parser.add_argument("--rtol", type=float,
                        help="accepted and ignored: a fixed-step program handed a tolerance, for the test that "
                             "a study by --tolerances catches it")
    args = parser.parse_args()
    problem, plan, parameters, terms, names, y = read_problem(args.input)
    t0 = float(plan["t0"])
    rhs = make_gas_rhs(parameters, t0, plan["j_min"]) if problem == "gas" else make_rhs(parameters, terms)
    y = midpoint(rhs, y, t0, float(plan["dt"]), int(plan["steps"]), args.slip)
    write_state(args.output, names, y, plan["run"])


if __name__ == "__main__":
    main()
